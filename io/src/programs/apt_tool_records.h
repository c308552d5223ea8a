// SPDX-License-Identifier: MIT
// ddfcam: APT tool and machine records (LOADTL, CUTTER, TLDATA, SPINDL, COOLNT, MSYS).
#pragma once

#include <ddfcam/planning/placement/cl_program.h>

#include "apt_lexer.h"

namespace ddfcam::io::detail {

/// @brief LOADTL/n[,...]: the tool number. @throws IoError unless n is a whole number >= 0.
void readLoadTool(const AptLexer& lexer, const AptRecord& r, planning::ClProgram& program);

/// @brief CUTTER/d[,r[,e,f,alpha,beta,h]] with lengths in the file unit (@p per mm each);
/// missing e and f follow from d and r. @throws IoError for non-numbers or > 7 values.
void readCutter(const AptLexer& lexer, const AptRecord& r, double per,
                planning::ClProgram& program);

/// @brief NX TLDATA/MILL,d,r,length,taper,tip as a cutter; other TLDATA kept as a comment
/// with a warning. @throws IoError for non-numbers.
void readToolData(const AptLexer& lexer, const AptRecord& r, double per,
                  planning::ClProgram& program);

/// @brief SPINDL/[RPM,]n[,CLW|CCLW] (the first non-zero speed is kept), SPINDL/OFF.
/// @throws IoError for non-numbers or a negative speed.
void readSpindle(const AptLexer& lexer, const AptRecord& r, planning::ClProgram& program);

/// @brief COOLNT/ON, FLOOD, MIST, ... switch the coolant on; COOLNT/OFF does not clear it.
void readCoolant(const AptRecord& r, planning::ClProgram& program);

/// @brief MSYS/x,y,z,xi,xj,xk,yi,yj,yk: a warning unless it is the identity (not applied).
/// @throws IoError unless there are 9 numbers.
void readMachineSystem(const AptLexer& lexer, const AptRecord& r, planning::ClProgram& program);

}  // namespace ddfcam::io::detail
