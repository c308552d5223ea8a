// SPDX-License-Identifier: MIT
// ddfcam gui: PathListWidget and path lengths.
#include <ddfcam/gui/path_list.h>

#include <QHeaderView>
#include <QLabel>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <optional>

namespace ddfcam::gui {

PathLengths pathLengths(const planning::ToolPath& path) {
  PathLengths out;
  out.lines = static_cast<int>(path.passStarts.size());
  const auto poses = static_cast<int>(path.poses.size());
  for (std::size_t s = 0; s < path.passStarts.size(); ++s) {
    const int begin = path.passStarts[s];
    const int end = s + 1 < path.passStarts.size() ? path.passStarts[s + 1] : poses;
    for (int i = begin + 1; i < end; ++i)
      out.cuttingMm += (path.poses[i].contact - path.poses[i - 1].contact).norm();
    if (begin > 0) out.idleMm += (path.poses[begin].contact - path.poses[begin - 1].contact).norm();
  }
  return out;
}

PathListWidget::PathListWidget(QWidget* parent) : QWidget(parent) {
  table_ = new QTableWidget(0, 4, this);
  table_->setObjectName("pathTable");
  table_->setHorizontalHeaderLabels({tr("Path"), tr("Lines"), tr("Cutting mm"), tr("Idle mm")});
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->verticalHeader()->setVisible(false);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->setMinimumHeight(120);
  total_ = new QLabel(this);
  total_->setObjectName("pathTotalLabel");
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(table_);
  layout->addWidget(total_);
  connect(table_, &QTableWidget::itemSelectionChanged, this,
          [this] { emit selectionChanged(selectedPath()); });
  connect(table_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    if (item->column() == 0) emit visibilityChanged(item->row(), item->checkState() == Qt::Checked);
  });
}

void PathListWidget::refresh(const planning::Project& project,
                             const std::function<bool(const std::string&)>& visible) {
  const int previous = selectedPath();
  const int oldRows = table_->rowCount();
  const int count = static_cast<int>(project.paths.size());
  {
    const QSignalBlocker block(table_);
    table_->setRowCount(count);
    PathLengths total;
    for (int r = 0; r < count; ++r) {
      PathLengths l = pathLengths(project.paths[r]);
      const std::optional<double>& linked = project.paths[r].linkedIdleMm;
      if (linked) l.idleMm = *linked;
      total.lines += l.lines;
      total.cuttingMm += l.cuttingMm;
      total.idleMm += l.idleMm;
      const QStringList cells = {QString::fromStdString(project.paths[r].name),
                                 QString::number(l.lines), QString::number(l.cuttingMm, 'f', 1),
                                 QString::number(l.idleMm, 'f', 1) +
                                     (linked ? tr(" (linked)") : QString())};
      for (int c = 0; c < cells.size(); ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        if (c > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table_->setItem(r, c, item);
      }
      // The name's box shows or hides the path in the view.
      QTableWidgetItem* name = table_->item(r, 0);
      name->setFlags(name->flags() | Qt::ItemIsUserCheckable);
      name->setCheckState(!visible || visible(project.paths[r].name) ? Qt::Checked
                                                                     : Qt::Unchecked);
      name->setToolTip(tr("Untick to hide the path in the view"));
    }
    total_->setText(tr("%1 paths, %2 lines: cutting %3 mm, idle %4 mm")
                        .arg(count)
                        .arg(total.lines)
                        .arg(total.cuttingMm, 0, 'f', 1)
                        .arg(total.idleMm, 0, 'f', 1));
    // A new path is what the user acts on next (smoothing); otherwise keep the selection.
    const int keep = count > oldRows || previous < 0 || previous >= count ? count - 1 : previous;
    if (keep >= 0) table_->selectRow(keep);
  }
  if (selectedPath() != previous) emit selectionChanged(selectedPath());
}

int PathListWidget::selectedPath() const {
  const QList<QTableWidgetItem*> items = table_->selectedItems();
  return items.isEmpty() ? -1 : items.front()->row();
}

void PathListWidget::selectPath(int index) {
  if (index < 0 || index >= table_->rowCount())
    table_->clearSelection();
  else
    table_->selectRow(index);
}

void PathListWidget::setPathChecked(int index, bool checked) {
  if (QTableWidgetItem* name = table_->item(index, 0))
    name->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

QString PathListWidget::totalText() const {
  return total_->text();
}

}  // namespace ddfcam::gui
