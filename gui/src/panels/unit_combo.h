// SPDX-License-Identifier: MIT
// ddfcam gui: a combo box of the length units a loaded mesh may be in (mm, cm, m, in).
#pragma once

#include <ddfcam/length_unit.h>

#include <QComboBox>
#include <QString>

namespace ddfcam::gui {

/// @brief A combo of mm, cm, m and in (item data: the LengthUnit), mm selected, named @p name,
/// with a tooltip saying the file's numbers are read in it.
inline QComboBox* makeUnitCombo(QWidget* parent, const char* name) {
  auto* combo = new QComboBox(parent);
  combo->setObjectName(name);
  for (LengthUnit unit :
       {LengthUnit::Millimetre, LengthUnit::Centimetre, LengthUnit::Metre, LengthUnit::Inch}) {
    const std::string_view symbol = unitSymbol(unit);
    combo->addItem(QString::fromLatin1(symbol.data(), static_cast<int>(symbol.size())),
                   static_cast<int>(unit));
  }
  combo->setToolTip(QObject::tr("Unit of the file's numbers (scaled to mm when read)"));
  return combo;
}

/// @brief The unit @p combo (from makeUnitCombo) shows.
inline LengthUnit unitOf(const QComboBox* combo) {
  return static_cast<LengthUnit>(combo->currentData().toInt());
}

/// @brief Selects @p unit in @p combo (from makeUnitCombo).
inline void selectUnit(QComboBox* combo, LengthUnit unit) {
  combo->setCurrentIndex(combo->findData(static_cast<int>(unit)));
}

}  // namespace ddfcam::gui
