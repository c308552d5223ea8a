// SPDX-License-Identifier: MIT
// One executable for the workbench's Qt Test classes: each test file registers its class with
// DDFCAM_GUI_TEST_MAIN(Class) instead of QTEST_MAIN, and gui_test_main.cpp runs the class
// named on the command line. Linking and moc-ing some thirty separate executables, each
// carrying the whole workbench, VTK and Qt, cost minutes of every fresh build; CTest still
// runs every class as its own test, in its own process and under its own X server.
#pragma once

#include <QObject>

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace ddfcam::test {

/// @brief How to run one registered Qt Test class: called before the QApplication exists
/// (the class's static initMain(), when it has one), then the factory of the test object.
struct GuiTestEntry {
  std::function<void()> beforeApplication;
  std::function<std::unique_ptr<QObject>()> create;
};

/// @brief Every registered class by name (the class name as written in the macro).
std::map<std::string, GuiTestEntry>& guiTestRegistry();

/// @brief Adds @p name to guiTestRegistry() at static initialisation; returns true.
bool registerGuiTest(const std::string& name, GuiTestEntry entry);

/// @brief Calls TestObject::initMain() when the class has one (as QTEST_MAIN does); a template,
/// so that a class without it is not an error.
template <class TestObject>
void callInitMain() {
  if constexpr (requires { TestObject::initMain(); }) TestObject::initMain();
}

}  // namespace ddfcam::test

/// Registers Qt Test class @p TestObject under its name; use once per class, at file scope,
/// where QTEST_MAIN would stand (the class's static initMain() runs as QTEST_MAIN runs it).
#define DDFCAM_GUI_TEST_MAIN(TestObject)                                                           \
  namespace {                                                                                      \
  const bool ddfcamGuiTestRegistered_##TestObject = ::ddfcam::test::registerGuiTest(               \
      #TestObject, ::ddfcam::test::GuiTestEntry{&::ddfcam::test::callInitMain<TestObject>, [] {    \
                                                  return std::unique_ptr<QObject>(new TestObject); \
                                                }});                                               \
  }
