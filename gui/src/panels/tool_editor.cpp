// SPDX-License-Identifier: MIT
// ddfcam gui: ToolEditor.
#include <ddfcam/gui/panels/tool_editor.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSpinBox>

namespace ddfcam::gui {

namespace {

using planning::ToolKind;

constexpr ToolKind kKinds[] = {ToolKind::CylinderRoll, ToolKind::BeltContactWheel,
                               ToolKind::BallEnd,      ToolKind::FlatEnd,
                               ToolKind::TorusCutter,  ToolKind::Sphere};

bool isWheel(ToolKind kind) {
  return kind == ToolKind::CylinderRoll || kind == ToolKind::BeltContactWheel;
}

}  // namespace

QString ToolEditor::kindName(ToolKind kind) {
  switch (kind) {
    case ToolKind::CylinderRoll:
      return tr("grinding roll");
    case ToolKind::Sphere:
      return tr("bare ball");
    case ToolKind::BeltContactWheel:
      return tr("belt contact wheel");
    case ToolKind::BallEnd:
      return tr("ball-end cutter");
    case ToolKind::FlatEnd:
      return tr("flat-end cutter");
    case ToolKind::TorusCutter:
      return tr("torus cutter");
  }
  return tr("unknown");
}

ToolEditor::ToolEditor(QWidget* parent) : QWidget(parent) {
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  name_ = new QLineEdit(this);
  name_->setObjectName("toolName");
  form->addRow(tr("Name"), name_);
  kind_ = new QComboBox(this);
  kind_->setObjectName("toolKind");
  for (const ToolKind k : kKinds) kind_->addItem(kindName(k), static_cast<int>(k));
  form->addRow(tr("Kind"), kind_);
  addLength(form, Radius, "toolRadius");
  addLength(form, Width, "toolWidth");
  addLength(form, EdgeRadius, "toolEdgeRadius");
  addLength(form, CrownRadius, "toolCrownRadius");
  addLength(form, ShankRadius, "toolShankRadius");
  addLength(form, ShankLength, "toolShankLength");
  addLength(form, HolderRadius, "toolHolderRadius");
  addLength(form, HolderLength, "toolHolderLength");
  addLength(form, ChordTolerance, "toolChordTolerance")->setDecimals(5);
  segments_ = new QSpinBox(this);
  segments_->setObjectName("toolSegments");
  segments_->setRange(0, 4096);
  segments_->setSpecialValueText(tr("from tolerance"));
  form->addRow(tr("Segments"), segments_);
  message_ = new QLabel(this);
  message_->setObjectName("toolMessage");
  message_->setWordWrap(true);
  message_->setStyleSheet("color: #c01010;");
  message_->hide();
  form->addRow(message_);
  connect(name_, &QLineEdit::editingFinished, this, &ToolEditor::emitIfChanged);
  connect(kind_, &QComboBox::activated, this, [this] {
    relabel(tool().kind);
    emitIfChanged();
  });
  connect(segments_, &QSpinBox::editingFinished, this, &ToolEditor::emitIfChanged);
  relabel(shown_.kind);
  setTool(shown_);
}

QDoubleSpinBox* ToolEditor::addLength(QFormLayout* form, Length which, const char* name) {
  auto* spin = new QDoubleSpinBox(this);
  spin->setObjectName(name);
  spin->setRange(0.0, 10000.0);
  spin->setDecimals(4);
  spin->setSuffix(tr(" mm"));
  spin->setKeyboardTracking(false);
  labels_[which] = new QLabel(this);
  lengths_[which] = spin;
  form->addRow(labels_[which], spin);
  connect(spin, &QDoubleSpinBox::editingFinished, this, &ToolEditor::emitIfChanged);
  return spin;
}

void ToolEditor::relabel(ToolKind kind) {
  const bool wheel = isWheel(kind);
  labels_[Radius]->setText(kind == ToolKind::BallEnd || kind == ToolKind::Sphere ? tr("Ball radius")
                           : wheel ? tr("Wheel radius")
                                   : tr("Cutter radius"));
  labels_[Width]->setText(wheel ? tr("Width") : tr("Flute length"));
  labels_[EdgeRadius]->setText(kind == ToolKind::TorusCutter ? tr("Corner radius")
                                                             : tr("Edge radius"));
  labels_[CrownRadius]->setText(tr("Crown radius"));
  labels_[ShankRadius]->setText(wheel ? tr("Arbor radius") : tr("Shank radius"));
  labels_[ShankLength]->setText(wheel ? tr("Arbor length") : tr("Shank length"));
  labels_[HolderRadius]->setText(wheel ? tr("Flange radius") : tr("Holder radius"));
  labels_[HolderLength]->setText(wheel ? tr("Flange thickness") : tr("Holder length"));
  labels_[ChordTolerance]->setText(tr("Chord tolerance"));
  // Fields a kind does not use stay visible but disabled, so a kind change keeps their values.
  const bool sphere = kind == ToolKind::Sphere;
  lengths_[Width]->setEnabled(!sphere);
  lengths_[EdgeRadius]->setEnabled(wheel || kind == ToolKind::TorusCutter);
  lengths_[CrownRadius]->setEnabled(wheel);
  for (const Length l : {ShankRadius, ShankLength, HolderRadius, HolderLength})
    lengths_[l]->setEnabled(!sphere);
}

void ToolEditor::setTool(const planning::Tool& tool) {
  filling_ = true;
  const QSignalBlocker block(this);
  name_->setText(QString::fromStdString(tool.name));
  kind_->setCurrentIndex(kind_->findData(static_cast<int>(tool.kind)));
  const double values[LengthCount] = {
      tool.radiusMm,       tool.widthMm,        tool.edgeRadiusMm,
      tool.crownRadiusMm,  tool.shankRadiusMm,  tool.shankLengthMm,
      tool.holderRadiusMm, tool.holderLengthMm, tool.chordToleranceMm};
  for (int i = 0; i < LengthCount; ++i) lengths_[i]->setValue(values[i]);
  segments_->setValue(tool.segments);
  relabel(tool.kind);
  shown_ = tool;
  filling_ = false;
}

planning::Tool ToolEditor::tool() const {
  planning::Tool t;
  t.name = name_->text().toStdString();
  t.kind = static_cast<ToolKind>(kind_->currentData().toInt());
  // A spin box rounds to its decimals: a field the user did not touch keeps its exact value.
  auto value = [this](Length l, double exact) {
    const double shown = lengths_[l]->value();
    return lengths_[l]->textFromValue(exact) == lengths_[l]->textFromValue(shown) ? exact : shown;
  };
  t.radiusMm = value(Radius, shown_.radiusMm);
  t.widthMm = value(Width, shown_.widthMm);
  t.edgeRadiusMm = value(EdgeRadius, shown_.edgeRadiusMm);
  t.crownRadiusMm = value(CrownRadius, shown_.crownRadiusMm);
  t.shankRadiusMm = value(ShankRadius, shown_.shankRadiusMm);
  t.shankLengthMm = value(ShankLength, shown_.shankLengthMm);
  t.holderRadiusMm = value(HolderRadius, shown_.holderRadiusMm);
  t.holderLengthMm = value(HolderLength, shown_.holderLengthMm);
  t.chordToleranceMm = value(ChordTolerance, shown_.chordToleranceMm);
  t.segments = segments_->value();
  return t;
}

void ToolEditor::emitIfChanged() {
  if (filling_) return;
  const planning::Tool now = tool();
  if (now == shown_) return;
  shown_ = now;
  emit edited();
}

void ToolEditor::setMessage(const QString& message) {
  message_->setText(message);
  message_->setVisible(!message.isEmpty());
}

QString ToolEditor::message() const {
  return message_->text();
}

}  // namespace ddfcam::gui
