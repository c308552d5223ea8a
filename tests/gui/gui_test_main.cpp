// SPDX-License-Identifier: MIT
// Entry point of ddfcam_gui_tests: `ddfcam_gui_tests CLASS [Qt Test options...]` runs one
// registered Qt Test class as QTEST_MAIN would (96-dpi application, its initMain() first);
// `ddfcam_gui_tests --list` prints the registered classes.
#include "gui_test_registry.h"

#include <QApplication>
#include <QtTest/QtTest>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace ddfcam::test {

std::map<std::string, GuiTestEntry>& guiTestRegistry() {
  static std::map<std::string, GuiTestEntry> registry;
  return registry;
}

bool registerGuiTest(const std::string& name, GuiTestEntry entry) {
  // Two classes of one name would silently leave one of them untested.
  if (!guiTestRegistry().emplace(name, std::move(entry)).second) {
    std::fprintf(stderr, "ddfcam_gui_tests: test class %s registered twice\n", name.c_str());
    std::abort();
  }
  return true;
}

}  // namespace ddfcam::test

namespace {

void printClasses(std::FILE* to) {
  for (const auto& [name, entry] : ddfcam::test::guiTestRegistry())
    std::fprintf(to, "  %s\n", name.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const auto& registry = ddfcam::test::guiTestRegistry();
  if (argc >= 2 && std::strcmp(argv[1], "--list") == 0) {
    printClasses(stdout);
    return 0;
  }
  const auto found = argc >= 2 ? registry.find(argv[1]) : registry.end();
  if (found == registry.end()) {
    std::fprintf(stderr, "usage: %s CLASS [Qt Test options]  (or --list); CLASS one of:\n",
                 argc > 0 ? argv[0] : "ddfcam_gui_tests");
    printClasses(stderr);
    return 2;
  }
  // Qt Test sees the program name and the options after the class.
  std::vector<char*> args{argv[0]};
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
  int qtArgc = static_cast<int>(args.size());
  found->second.beforeApplication();
  QApplication app(qtArgc, args.data());
  app.setAttribute(Qt::AA_Use96Dpi, true);
  const std::unique_ptr<QObject> test = found->second.create();
  return QTest::qExec(test.get(), qtArgc, args.data());
}
