# SPDX-License-Identifier: MIT
# Compile options shared by every ddfcam target, applied through the interface target ddfcam_options.
add_library(ddfcam_options INTERFACE)
target_compile_options(ddfcam_options INTERFACE -Wall -Wextra -Wpedantic -Wno-sign-compare)
if(DDFCAM_STRICT_WARNINGS)
  target_compile_options(ddfcam_options INTERFACE -Werror)
endif()
if(DDFCAM_NATIVE)
  target_compile_options(ddfcam_options INTERFACE -march=native)
  target_compile_definitions(ddfcam_options INTERFACE DDFCAM_NATIVE_BUILD=1)
endif()
if(DDFCAM_SANITIZER)
  target_compile_options(ddfcam_options INTERFACE -fsanitize=${DDFCAM_SANITIZER} -fno-omit-frame-pointer)
  target_link_options(ddfcam_options INTERFACE -fsanitize=${DDFCAM_SANITIZER})
endif()

# ddfcam_precompile_headers(<target> <set>): precompiled headers for a target with many sources.
# Parsing Eigen, GoogleTest or Qt again in each of a target's sources was a large part of a
# fresh build on two cores; a header set is compiled once per target instead. Sets: `eigen`
# (the libraries), `gtest` (the GoogleTest suites), `qt` (the workbench and its Qt Test
# classes). Off with -DDDFCAM_PRECOMPILED_HEADERS=OFF (e.g. to check that every source
# includes what it uses).
option(DDFCAM_PRECOMPILED_HEADERS "Precompile the heaviest third-party headers per target" ON)
function(ddfcam_precompile_headers target set)
  if(NOT DDFCAM_PRECOMPILED_HEADERS)
    return()
  endif()
  set(common <algorithm> <cmath> <functional> <memory> <optional> <string> <vector>
             <Eigen/Core> <Eigen/Geometry>)
  if(set STREQUAL "eigen")
    target_precompile_headers(${target} PRIVATE ${common})
  elseif(set STREQUAL "gtest")
    target_precompile_headers(${target} PRIVATE ${common} <gtest/gtest.h> <gmock/gmock.h>)
  elseif(set STREQUAL "qt")
    target_precompile_headers(${target} PRIVATE ${common} <QObject> <QString> <QWidget>
                              <QAction> <QComboBox> <QDoubleSpinBox> <QLabel> <QPushButton>
                              <vtkActor.h> <vtkPolyData.h> <vtkRenderer.h> <vtkSmartPointer.h>)
  else()
    message(FATAL_ERROR "ddfcam_precompile_headers: unknown set '${set}'")
  endif()
endfunction()
