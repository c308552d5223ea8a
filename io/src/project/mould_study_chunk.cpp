// SPDX-License-Identifier: MIT
// ddfcam: encoding and bounds-checked decoding of the "MOLD" chunk (mould study).
#include "mould_study_chunk.h"

#include <ddfcam/error.h>
#include <ddfcam/io/mesh/ddf_file.h>

#include "../common/byte_codec.h"

#include <exception>

namespace ddfcam::io::detail {
namespace {

void putI32(std::string& out, int value) {
  putU32(out, static_cast<std::uint32_t>(value));
}

void putCount(std::string& out, std::size_t count) {
  putU64(out, static_cast<std::uint64_t>(count));
}

void putFlag(std::string& out, bool value) {
  out += static_cast<char>(value ? 1 : 0);
}

bool readFlag(PayloadReader& in, const char* what) {
  const std::uint8_t value = in.u8(what);
  if (value > 1) in.fail(std::string(what) + " must be 0 or 1, found " + std::to_string(value));
  return value == 1;
}

void putVec3List(std::string& out, const std::vector<ddf::Vec3>& points) {
  putCount(out, points.size());
  for (const ddf::Vec3& p : points) putVec3(out, p);
}

std::vector<ddf::Vec3> readVec3List(PayloadReader& in, const char* what) {
  std::vector<ddf::Vec3> out(in.count(24, what));
  for (ddf::Vec3& p : out) p = readVec3(in, what);
  return out;
}

// An embedded .ddf: u32 byte count + its complete encoding (checksum included).
ddf::DisplacementField readDdf(PayloadReader& in, const std::string& what) {
  const std::string bytes = in.string("embedded .ddf");
  try {
    return decodeDdf(bytes, what);
  } catch (const Error&) {
    std::throw_with_nested(IoError(in.context() + ": " + what + " is not a valid .ddf encoding"));
  }
}

void putSurface(std::string& out, const planning::LoadedSurface& surface) {
  putString(out, surface.name);
  putString(out, surface.sourcePath);
  putDesignMesh(out, surface.mesh);
  putCount(out, surface.fields.size());
  for (const planning::MeshField& field : surface.fields) {
    putString(out, field.name);
    putString(out, field.unit);
    putFlag(out, field.perCell);
    putFloatList(out, field.values);
  }
}

planning::LoadedSurface readSurface(PayloadReader& in) {
  planning::LoadedSurface surface;
  surface.name = in.string("surface name");
  surface.sourcePath = in.string("surface source path");
  surface.mesh = readDesignMesh(in);
  // A field takes at least 4 + 4 + 1 + 8 bytes.
  surface.fields.resize(in.count(17, "surface field"));
  for (planning::MeshField& field : surface.fields) {
    field.name = in.string("field name");
    field.unit = in.string("field unit");
    field.perCell = readFlag(in, "field per-cell flag");
    field.values = readFloatList(in, "field values");
  }
  return surface;
}

void putAlignment(std::string& out, const planning::SurfaceAlignmentRecord& alignment) {
  putI32(out, static_cast<int>(alignment.method));
  for (double value : alignment.transform) putF64(out, value);
  putF64(out, alignment.rmsMm);
  putCount(out, alignment.pointPairs.size());
  for (const auto& pair : alignment.pointPairs) {
    putVec3(out, pair[0]);
    putVec3(out, pair[1]);
  }
}

planning::SurfaceAlignmentRecord readAlignment(PayloadReader& in) {
  planning::SurfaceAlignmentRecord alignment;
  alignment.method = static_cast<planning::AlignmentMethod>(in.i32("alignment method"));
  for (double& value : alignment.transform) value = in.f64("alignment transform");
  alignment.rmsMm = in.f64("alignment RMS");
  alignment.pointPairs.resize(in.count(48, "alignment point pair"));
  for (auto& pair : alignment.pointPairs) {
    pair[0] = readVec3(in, "alignment point pair");
    pair[1] = readVec3(in, "alignment point pair");
  }
  return alignment;
}

void putParams(std::string& out, const planning::ComparisonParams& params) {
  putI32(out, params.resolution);
  putF64(out, params.band.lowerMm);
  putF64(out, params.band.upperMm);
  putFlag(out, params.flipNormal);
  putF64(out, params.sequence.reachMm);
  putF64(out, params.sequence.crustSafety);
  putI32(out, params.sequence.maxStages);
}

planning::ComparisonParams readParams(PayloadReader& in) {
  planning::ComparisonParams params;
  params.resolution = in.i32("comparison resolution");
  params.band.lowerMm = in.f64("comparison band");
  params.band.upperMm = in.f64("comparison band");
  params.flipNormal = readFlag(in, "flip-normal flag");
  params.sequence.reachMm = in.f64("sequence reach");
  params.sequence.crustSafety = in.f64("sequence crust safety");
  params.sequence.maxStages = in.i32("sequence stage limit");
  return params;
}

void putStatistics(std::string& out, const planning::ErrorStatistics& s) {
  for (double value : {s.maxMm, s.minMm, s.meanMm, s.rmsMm, s.inTolerancePercent,
                       s.materialLeftPercent, s.overcutPercent, s.areaMm2})
    putF64(out, value);
  putCount(out, s.points);
}

planning::ErrorStatistics readStatistics(PayloadReader& in) {
  planning::ErrorStatistics s;
  for (double* value : {&s.maxMm, &s.minMm, &s.meanMm, &s.rmsMm, &s.inTolerancePercent,
                        &s.materialLeftPercent, &s.overcutPercent, &s.areaMm2})
    *value = in.f64("statistics");
  s.points = static_cast<std::size_t>(in.u64("statistics point count"));
  return s;
}

void putComparison(std::string& out, const planning::SurfaceComparison& result) {
  const ddf::DeformationSequence& sequence = result.sequence;
  putCount(out, sequence.stages.size());
  for (const ddf::DeformationStage& stage : sequence.stages) {
    putString(out, encodeDdf(stage.ddf));
    putF64(out, stage.fraction);
    putIntList(out, stage.crossingFaces);
  }
  putVec3List(out, sequence.deformedPoints);
  putIntList(out, sequence.crossingFaces);
  putIntList(out, sequence.unresolvedFaces);
  putCount(out, sequence.missingPoints);
  putField(out, result.deviation);
  putVec3List(out, result.deviationVectors);
  putStatistics(out, result.statistics);
  putF64(out, result.band.lowerMm);
  putF64(out, result.band.upperMm);
}

planning::SurfaceComparison readComparison(PayloadReader& in) {
  planning::SurfaceComparison result;
  ddf::DeformationSequence& sequence = result.sequence;
  // A stage takes at least 4 + 8 + 8 bytes.
  sequence.stages.resize(in.count(20, "deformation stage"));
  for (std::size_t s = 0; s < sequence.stages.size(); ++s) {
    ddf::DeformationStage& stage = sequence.stages[s];
    stage.ddf = readDdf(in, "the DDF of deformation stage " + std::to_string(s));
    stage.fraction = in.f64("stage fraction");
    stage.crossingFaces = readIntList(in, "stage crossing faces");
  }
  sequence.deformedPoints = readVec3List(in, "deformed points");
  sequence.crossingFaces = readIntList(in, "crossing faces");
  sequence.unresolvedFaces = readIntList(in, "unresolved faces");
  sequence.missingPoints = static_cast<std::size_t>(in.u64("missing point count"));
  result.deviation = readField(in);
  result.deviationVectors = readVec3List(in, "deviation vectors");
  result.statistics = readStatistics(in);
  result.band.lowerMm = in.f64("comparison band");
  result.band.upperMm = in.f64("comparison band");
  return result;
}

void putHistory(std::string& out, const planning::CompensationHistory& history) {
  putString(out, encodeDdf(history.target));
  putCount(out, history.iterations.size());
  for (const planning::CompensationIteration& it : history.iterations) {
    putFloatList(out, it.mouldHeights);
    putFloatList(out, it.formedHeights);
    putString(out, it.formedSource);
    putF64(out, it.maxDeviationMm);
    putF64(out, it.rmsDeviationMm);
    putF64(out, it.lambda);
    putCount(out, it.pointsOutsideCrust);
  }
}

planning::CompensationHistory readHistory(PayloadReader& in) {
  planning::CompensationHistory history;
  history.target = readDdf(in, "the compensation target DDF");
  // An iteration takes at least 8 + 8 + 4 + 4 x 8 bytes.
  history.iterations.resize(in.count(52, "compensation iteration"));
  for (planning::CompensationIteration& it : history.iterations) {
    it.mouldHeights = readFloatList(in, "mould heights");
    it.formedHeights = readFloatList(in, "formed heights");
    it.formedSource = in.string("formed source");
    it.maxDeviationMm = in.f64("iteration max deviation");
    it.rmsDeviationMm = in.f64("iteration RMS deviation");
    it.lambda = in.f64("iteration lambda");
    it.pointsOutsideCrust = static_cast<std::size_t>(in.u64("points outside the crust"));
  }
  return history;
}

}  // namespace

void putMouldStudy(std::string& out, const planning::MouldStudy& study) {
  putSurface(out, study.mould);
  putFlag(out, study.formed.has_value());
  if (study.formed) putSurface(out, *study.formed);
  putAlignment(out, study.alignment);
  putParams(out, study.comparison);
  putFlag(out, study.result.has_value());
  if (study.result) putComparison(out, *study.result);
  putFlag(out, study.compensation.has_value());
  if (study.compensation) putHistory(out, *study.compensation);
}

planning::MouldStudy readMouldStudy(PayloadReader& in) {
  planning::MouldStudy study;
  study.mould = readSurface(in);
  if (readFlag(in, "formed-surface flag")) study.formed = readSurface(in);
  study.alignment = readAlignment(in);
  study.comparison = readParams(in);
  if (readFlag(in, "result flag")) study.result = readComparison(in);
  if (readFlag(in, "compensation flag")) study.compensation = readHistory(in);
  return study;
}

}  // namespace ddfcam::io::detail
