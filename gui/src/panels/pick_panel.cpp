// SPDX-License-Identifier: MIT
// ddfcam gui: PickPanel.
#include <ddfcam/gui/panels/pick_panel.h>

#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_view.h>

#include <QLabel>
#include <QVBoxLayout>

namespace ddfcam::gui {

PickPanel::PickPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  label_ = new QLabel(tr("Click on the part to pick a surface point."), this);
  label_->setObjectName("pickSummary");
  label_->setWordWrap(true);
  label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  label_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(label_);
  layout->addStretch(1);
  connect(&workbench.partView, &PartView::picked, this, &PickPanel::show);
  connect(&workbench.document, &Document::changed, this, [this](Changes what) {
    if (what & Change::Part) label_->setText(tr("Click on the part to pick a surface point."));
  });
}

QString PickPanel::text() const {
  return label_->text();
}

void PickPanel::show(const PickResult& pick) {
  const ddf::SurfaceLocation& l = pick.location;
  QString text = tr("face %1\nbarycentric (%2, %3, %4)\nh = %5\npoint (%6, %7, %8) mm")
                     .arg(l.face)
                     .arg(l.bary.x(), 0, 'f', 4)
                     .arg(l.bary.y(), 0, 'f', 4)
                     .arg(l.bary.z(), 0, 'f', 4)
                     .arg(l.h, 0, 'f', 5)
                     .arg(l.point.x(), 0, 'f', 4)
                     .arg(l.point.y(), 0, 'f', 4)
                     .arg(l.point.z(), 0, 'f', 4);
  if (pick.fieldValue)
    text += tr("\n%1 = %2 %3")
                .arg(QString::fromStdString(pick.fieldName))
                .arg(*pick.fieldValue, 0, 'g', 6)
                .arg(QString::fromStdString(pick.fieldUnit));
  label_->setText(text);
}

}  // namespace ddfcam::gui
