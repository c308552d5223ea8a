// SPDX-License-Identifier: MIT
// ddfcam gui: PartPanel.
#include <ddfcam/gui/panels/part_panel.h>

#include <ddfcam/gui/document.h>
#include <ddfcam/gui/part_view.h>
#include <ddfcam/gui/project_actions.h>
#include <ddfcam/planning/model/field_statistics.h>

#include <QLabel>
#include <QVBoxLayout>

namespace ddfcam::gui {

namespace {

QString row(const QString& name, const QString& value) {
  return QString("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(name, value.toHtmlEscaped());
}

QString text(const std::string& s) {
  return QString::fromStdString(s);
}

QString mm(double value) {
  return QObject::tr("%1 mm").arg(value, 0, 'g', 3);
}

QString unitRow(const planning::Project& p, const std::optional<io::LoadPartReport>& report) {
  const QString unit = text(std::string(unitSymbol(p.sourceUnit)));
  const bool fromFile = report && report->unitFromFile;
  return row(QObject::tr("Came in"), fromFile ? QObject::tr("%1 (from file)").arg(unit) : unit);
}

// What the import measured and did; only the session that imported the part knows it.
QString importRows(const io::LoadPartReport& r) {
  QString html;
  if (r.reduction.inputFaces > 0)
    html += row(QObject::tr("Reduction"), QObject::tr("%L1 -> %L2 faces in %3 s")
                                              .arg(r.reduction.inputFaces)
                                              .arg(r.reduction.supportFaces)
                                              .arg(r.reduction.seconds, 0, 'f', 1));
  if (r.accuracy.measured)
    html += row(QObject::tr("Distances"),
                QObject::tr("input -> DDF %1, DDF -> input %2")
                    .arg(mm(r.accuracy.inputToDdfMm), mm(r.accuracy.ddfToInputMm)));
  if (r.stock)
    html +=
        row(QObject::tr("Stock"),
            r.stock->holds ? QObject::tr("%1 held").arg(mm(r.stock->requestedMm))
                           : QObject::tr("%1 NOT held: %2")
                                 .arg(mm(r.stock->requestedMm),
                                      r.stock->limit ? text(r.stock->limit->message) : QString()));
  return html;
}

QString factRows(const ddf::DisplacementField& f, const PartFacts& facts) {
  QString html = row(QObject::tr("Size"), text(sizeLine(facts.sizeMm())));
  html += row(QObject::tr("Support"),
              QObject::tr("%L1 faces, %L2 vertices").arg(f.faceCount()).arg(f.vertexCount()));
  html += row(QObject::tr("Raster"), QObject::tr("m = %1, spacing %2, %L3 points")
                                         .arg(f.resolution())
                                         .arg(mm(facts.rasterSpacingMm))
                                         .arg(static_cast<qulonglong>(f.topology().pointCount())));
  if (facts.reach) {
    html += row(QObject::tr("Crust above"), text(reachLine(*facts.reach, true)));
    html += row(QObject::tr("Crust below"), text(reachLine(*facts.reach, false)));
  }
  return html;
}

QString partRows(const planning::Project& p, const PartGeometry* geometry, const PartFacts* facts,
                 const std::optional<io::LoadPartReport>& report) {
  const ddf::DisplacementField& f = *p.part;
  QString html = row(QObject::tr("Part"), QString::fromStdString(p.partName));
  if (!p.sourcePath.empty())
    html += row(QObject::tr("Source"), QString::fromStdString(p.sourcePath));
  html += unitRow(p, report);
  if (facts) html += factRows(f, *facts);
  if (!p.cadFaceNames.empty())
    html += row(QObject::tr("CAD faces"), QObject::tr("%L1").arg(p.cadFaceNames.size()));
  if (report) html += importRows(*report);
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
  if (workbench.projectActions)
    connect(workbench.projectActions, &ProjectActions::partReportChanged, this,
            &PartPanel::refresh);
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
  static const std::optional<io::LoadPartReport> kNone;
  ProjectActions* actions = workbench().projectActions;
  // The report belongs to the part only while the document still holds that import.
  const bool imported = actions && actions->partReport() && !p.sourcePath.empty();
  QString html = "<table cellspacing='4'>" + partRows(p, workbench().partView.geometry(),
                                                      workbench().partView.facts(),
                                                      imported ? actions->partReport() : kNone);
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
