// SPDX-License-Identifier: MIT
// ddfcam gui: small widget factories shared by the Mould tools panel's groups (private).
#pragma once

#include <QDoubleSpinBox>
#include <QString>

namespace ddfcam::gui::mould_tools {

/// A spin box with two decimals over [low, high], named @p name (tests find it by it).
inline QDoubleSpinBox* decimalSpin(QWidget* parent, const char* name, double low, double high,
                                   double value, const QString& suffix = {}) {
  auto* spin = new QDoubleSpinBox(parent);
  spin->setObjectName(name);
  spin->setDecimals(2);
  spin->setRange(low, high);
  spin->setValue(value);
  spin->setSuffix(suffix);
  return spin;
}

}  // namespace ddfcam::gui::mould_tools
