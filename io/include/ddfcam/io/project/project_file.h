// SPDX-License-Identifier: MIT
// ddfcam: the .ddfproj binary file format of a workbench project (planning::Project).
#pragma once

#include <ddfcam/planning/model/project.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io {

/// @brief Project format version this build writes and the newest it reads (it reads 1, 2 and
/// 3 too).
inline constexpr std::uint32_t kProjectFormatVersion = 4;

/// @brief What decodeProject found besides the project itself.
struct ProjectReadReport {
  /// Format version of the file read (1 to 4; default 0 before a read).
  std::uint32_t formatVersion = 0;
  /// Optional chunks this build does not know and skipped, as "<source>: chunk 5 ('note')",
  /// in file order (default empty). Their content is not loaded and is not saved again.
  std::vector<std::string> skippedChunks;
};

/// @brief Serialises @p project in the .ddfproj format (format version kProjectFormatVersion).
///
/// Every number is little-endian and written byte by byte (host order does not matter); f32/f64
/// are IEEE bit patterns (NaN payloads survive); i32 is two's complement; a string is a u32 byte
/// count followed by the bytes (UTF-8 by convention, stored unchanged).
///
/// | offset | size | field |
/// |---|---|---|
/// | 0 | 8 | magic "DDFPRJ\x1a\n" (a .ddf starts with "DDFCAM\x1a\n") |
/// | 8 | 4 | u32 format version |
/// | 12 | 4 | u32 chunk count C |
/// | 16 | 8 | u64 total file size in bytes, checksum included |
/// | 24 | | C chunks: 4-byte ASCII tag, u64 payload size L, L payload bytes |
/// | end-4 | 4 | u32 CRC-32 (IEEE, zlib) of every byte before it |
///
/// Optional chunks: a tag whose first character is a lower-case ASCII letter ('a' to 'z') marks
/// a chunk that a reader may ignore without misreading anything else. A reader skips such a
/// chunk when it does not know the tag, and reports the skip (ProjectReadReport::skippedChunks
/// and a warning through ddfcam::log); the envelope (size, checksum) still covers it. A later
/// version adds self-contained data (notes, thumbnails, caches, new item kinds) as optional
/// chunks without raising the format version. Data an older reader must not ignore (a changed
/// payload of an existing tag, or a chunk that changes the meaning of others) takes an
/// upper-case tag and a version bump. Any other unknown tag is an error.
///
/// Chunks of version 4 (all upper-case, so none is optional). "PROJ" comes first; the others may
/// follow in any order (encodeProject writes them in the order of this table), and the order of
/// the chunks with one tag is the order of the project's vector:
/// | tag | count | payload |
/// |---|---|---|
/// | "PROJ" | 1 | string partName, string sourcePath |
/// | "PART" | 0..1 | the part: its complete .ddf encoding (encodeDdf, ddf_file.h) |
/// | "DSGN" | 0..1 | design mesh: u64 V, u64 T, V x 3 f64 (mm), T x 3 i32 vertex indices |
/// | "TOOL" | per tool | string name, i32 kind, f64 radiusMm, f64 widthMm, i32 segments, sizes |
/// | "PATH" | per path | string name, i32 tool, f64 feed, u64 P, P poses, u64 S, S i32 |
/// | "FELD" | per field | string name, string unit, u8 isSigned 0/1, u64 N, N f32 values |
/// | "REGN" | per region | string name, 3 f32 colour RGB, u64 N, N i32 support faces, plan |
/// | "STAT" | per state | string name, u64 N, N f32 heights |
/// | "SURF" | per surface | string name, then to the payload's end the .ddf encoding |
/// | "MOLD" | 0..1 | the mould study (planning::MouldStudy, from version 4 on), below |
///
/// Optional chunk of this build (lower-case, so older builds skip it with a warning):
/// | tag | count | payload |
/// |---|---|---|
/// | "prov" | 0..1 | where the part came from, below |
/// | "line" | per planned path | the raw lines and linking of a path, below |
/// | "hdig" | per field with a digest | i32 field index (a "FELD" before it), u64 digest |
///
/// "hdig": the digest is planning::ScalarField::heightsDigest, the heights the field was
/// computed from; a field without it is never reported stale.
///
/// "prov": i32 source unit (0 mm, 1 cm, 2 m, 3 in), u64 N, N strings (the CAD face names),
/// u64 F, F i32 (per support face of the part its CAD face, -1 or < N; F is 0 or the part's
/// face count). It is written only for a part read in a unit other than mm or with CAD faces, so
/// other projects are saved as before; without it a project loads with sourceUnit mm and no CAD
/// faces. A reader ignores bytes after the members it knows (later members extend it).
///
/// "line": i32 path index (position among the "PATH" chunks, which come before it), u8
/// hasLinkedIdle 0/1, f64 linkedIdleMm (0 when not linked), u64 L raw lines, then per line i32
/// stop, i32 backwardStop (Streamline::StopReason values), u64 seedIndex, f64 lengthMm, u64 P
/// points, P x (i32 support face, 3 f64 bary, f64 h, 3 f64 point mm). It is written only for a
/// path with raw lines or a linked idle length (ToolPath::rawLines, linkedIdleMm), so other
/// projects are saved as before; without it a path loads with neither. A reader ignores bytes
/// after the members it knows.
///
/// The S i32 of a path are its passStarts, the feed is feedMmPerMin (mm/min), kind is the
/// ToolKind value.
///
/// The sizes of a tool (from version 3 on) are 7 f64 (mm): edgeRadiusMm, crownRadiusMm,
/// shankRadiusMm, shankLengthMm, holderRadiusMm, holderLengthMm, chordToleranceMm.
///
/// The plan of a region (planning::RegionPlan, from version 2 on) is: i32 tool, i32 flowSource,
/// 3 f64 fixedDirection, u8 smoothField 0/1, f64 smoothnessWeight, i32 spacingMode, f64
/// spacingMm, f64 scallopToleranceMm, i32 feedSign, i32 linking, u64 S strokes, then per stroke
/// u64 P and P x 3 f64 points (mm). Enums are stored as their values.
///
/// Version 2 differs only in "TOOL": its payload ends after the segments (tools were bare rolls
/// and balls); a version-2 file loads with the later fields at planning::Tool's defaults (0,
/// chord tolerance 0.005 mm) and the stored segment count. Version 1 differs from version 2
/// also in "REGN": its payload ends after the faces, and its regions load with the default
/// RegionPlan. Version 3 differs from version 4 only in having no "MOLD" chunk (in a version-3
/// file it is an unknown chunk). Saving always writes version 4.
///
/// The mould study ("MOLD"; flags are u8 0/1, a "ddf" is a u32 byte count followed by the
/// complete .ddf encoding, a "list" is u64 N followed by N values, i32 faces or f32 values):
/// surface mould; u8 hasFormed, [surface formed]; alignment: i32 method, 16 f64 transform
/// (row-major), f64 rmsMm, u64 P, P x (3 f64 formed point, 3 f64 mould point); comparison
/// params: i32 resolution, f64 band lower, f64 band upper, u8 flipNormal, f64 reachMm, f64
/// crustSafety, i32 maxStages (the progress callback is not stored); u8 hasResult, [result];
/// u8 hasCompensation, [history]. A surface is string name, string sourcePath, the mesh as in
/// "DSGN", u64 F fields, each string name, string unit, u8 perCell, list of f32 values. A result
/// is u64 S stages, each ddf, f64 fraction, list of crossing faces; u64 N deformedPoints, N x 3
/// f64 (mm); lists of crossing and of unresolved faces; u64 missingPoints; the deviation as a
/// "FELD" payload; u64 N deviation vectors, N x 3 f64 (mm); statistics: f64 max, min, mean, rms,
/// inTolerancePercent, materialLeftPercent, overcutPercent, areaMm2, u64 points; band: f64
/// lower, f64 upper. A history is the target ddf, u64 I iterations, each list of f32
/// mouldHeights, list of f32 formedHeights, string formedSource, f64 maxDeviationMm, f64
/// rmsDeviationMm, f64 lambda, u64 pointsOutsideCrust.
///
/// A pose is 19 f64: the 4 x 4 matrix of PathPose::pose in column-major order (bottom row
/// included, so the stored matrix is exactly the one in memory), then the contact x y z (mm).
/// Embedding the .ddf encoding restores positions, vectors, face vertex order and heights
/// bit-exactly.
/// @return the file content.
/// @throws InvalidInput if @p project violates planning::validateProject (nothing is encoded).
std::string encodeProject(const planning::Project& project);

/// @brief Rebuilds a project from .ddfproj content; the exact inverse of encodeProject
/// (planning::projectsEqual holds between the original and the decoded project).
/// Reads format versions 1 to 4; skips unknown optional chunks (see encodeProject).
/// @param bytes whole file content. @param sourceName file name used in messages.
/// @param report if not null, receives the file's version and the skipped optional chunks.
/// @throws IoError naming @p sourceName and the problem if the content is empty, truncated
/// (the message names the chunk where it ends), not a project file, of a newer format version,
/// damaged (checksum mismatch), holds an unknown upper-case or a misplaced chunk, a chunk whose
/// payload does not parse, or values that violate planning::validateProject (the InvalidInput
/// is nested).
planning::Project decodeProject(std::string_view bytes, const std::string& sourceName,
                                ProjectReadReport* report = nullptr);

/// @brief Writes @p project to @p path atomically (temporary file in the same directory +
/// rename): on any failure the previous content of @p path, if any, is left unchanged.
/// @throws InvalidInput as encodeProject (the file is not touched).
/// @throws IoError if the file cannot be written (missing directory, disk full, ...).
void writeProject(const planning::Project& project, const std::filesystem::path& path);

/// @brief Reads a .ddfproj file written by writeProject (any version decodeProject reads).
/// @param report if not null, receives the file's version and the skipped optional chunks.
/// @throws IoError if the file is missing or unreadable, or as decodeProject.
planning::Project readProject(const std::filesystem::path& path,
                              ProjectReadReport* report = nullptr);

}  // namespace ddfcam::io
