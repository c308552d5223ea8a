// SPDX-License-Identifier: MIT
// ddfcam gui: PartPanel.
#include <ddfcam/gui/panels/part_panel.h>

#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/planning/field_statistics.h>

#include <QLabel>
#include <QVBoxLayout>

namespace ddfcam::gui {

namespace {

QString row(const QString& name, const QString& value) {
  return QString("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(name, value.toHtmlEscaped());
}

QString partRows(const planning::Project& p, const PartGeometry* geometry) {
  const ddf::DisplacementField& f = *p.part;
  QString html = row(QObject::tr("Part"), QString::fromStdString(p.partName));
  if (!p.sourcePath.empty())
    html += row(QObject::tr("Source"), QString::fromStdString(p.sourcePath));
  html += row(QObject::tr("Support"),
              QObject::tr("%L1 faces, %L2 vertices").arg(f.faceCount()).arg(f.vertexCount()));
  html += row(QObject::tr("Raster"), QObject::tr("m = %1, %L2 points")
                                         .arg(f.resolution())
                                         .arg(static_cast<qulonglong>(f.topology().pointCount())));
  html += row(QObject::tr("Memory"),
              QObject::tr("%1 MB").arg(static_cast<double>(f.memoryBytes()) / 1e6, 0, 'f', 2));
  if (const auto range = planning::fieldRange(f.allHeights()))
    html += row(QObject::tr("Heights h"),
                QString("%1 .. %2").arg(range->min, 0, 'f', 4).arg(range->max, 0, 'f', 4));
  if (geometry)
    html += row(QObject::tr("Shown surface"),
                geometry->adaptiveSurface
                    ? QObject::tr("%L1 triangles, adaptive (eps %2 mm)")
                          .arg(static_cast<qulonglong>(geometry->surfaceTriangles))
                          .arg(geometry->adaptiveEpsMm, 0, 'g', 2)
                    : QObject::tr("%L1 triangles, raster mesh")
                          .arg(static_cast<qulonglong>(geometry->surfaceTriangles)));
  if (p.designMesh)
    html += row(
        QObject::tr("Design mesh"),
        QObject::tr("%L1 triangles").arg(static_cast<qulonglong>(p.designMesh->triangles.size())));
  return html;
}

}  // namespace

PartPanel::PartPanel(Workbench& workbench, QWidget* parent) : Panel(workbench, parent) {
  label_ = new QLabel(this);
  label_->setObjectName("partSummary");
  label_->setTextFormat(Qt::RichText);
  label_->setWordWrap(true);
  label_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(label_);
  layout->addStretch(1);
  connect(&workbench.document, &Document::changed, this, &PartPanel::refresh);
  connect(&workbench.partView, &PartView::geometryChanged, this, &PartPanel::refresh);
  refresh();
}

QString PartPanel::text() const {
  return label_->text();
}

void PartPanel::refresh() {
  const planning::Project& p = workbench().document.project();
  if (!p.part) {
    label_->setText(
        tr("No part. Open a project, a .ddf or a mesh (File > Open), or drop one "
           "onto the window."));
    return;
  }
  QString html = "<table cellspacing='4'>" + partRows(p, workbench().partView.geometry());
  html += row(tr("Document"), tr("%1 fields, %2 regions, %3 tools, %4 paths, %5 states, "
                                 "%6 surfaces")
                                  .arg(p.fields.size())
                                  .arg(p.regions.size())
                                  .arg(p.tools.size())
                                  .arg(p.paths.size())
                                  .arg(p.states.size())
                                  .arg(p.surfaces.size()));
  label_->setText(html + "</table>");
}

}  // namespace ddfcam::gui
