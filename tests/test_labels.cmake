# SPDX-License-Identifier: MIT
# Which tests are `slow` and which need ../shared/data (`data`), by test name: gtest names
# (Suite.Test, Prefix/Suite.Test/Param) for discovered tests, CTest names for add_test tests.
# Patterns as in --gtest_filter (`*`, `?`). A test not listed as slow is `fast`.
# Read by ddfcam_discover_tests and ddfcam_label_plain_tests (cmake/DdfcamTests.cmake).
#
# Slow means over 1 s in build/Testing/Temporary/CTestCostData.txt of a full `ctest -j2` run;
# scripts/check-test-labels lists the fast tests that took longer after a run (docs/testing.md).
# A whole suite is named with `.*` only when all of its tests are slow.

set(DDFCAM_SLOW_TESTS
  # ddfcam_ddf_tests
  DeformationSequence.SharedSpringbackPairLandsOnTheFormedPart
  DepthBuffer.SphereCutByPlanesMatchesAnalyticHeights
  MeshConversion.BunnyConvertsToAValidDdf
  MeshConversionAccuracy.InputSupportMeetsAnyToleranceAtTheFirstTry
  MeshConversionAccuracy.ReducedCylinderStaysWithinTolerance
  MeshConversionAccuracy.ReducedSphereStaysWithinTolerance
  MeshConversionAccuracy.StockFitKeepsTheSurfaceWithinTolerance
  StockCrust.ConcaveCylinderHoldsAStockBelowItsRadius
  StockCrust.ConcaveCylinderRefusesAStockBeyondItsRadius
  StubbleProbe.GridLocalizationEqualsBruteForceForABallAndTwoRollsOnASaddle
  # ddfcam_ddf_shared_tests, ddfcam_stock_crust_shared_tests
  IncrementalTriangulationShared.*
  MeshConversionShared.*
  StockCrustParts.*
  # ddfcam_planning_tests
  CrustClamping.CutsDeeperThanTheCrustAreCountedAndBoundTheMinimum
  Curvature.AccuracyTableConvergesToTheRoundingFloor
  DemoProject.SimulatedPassesGrindTheContactLinesAndNothingFarFromThem
  DesignCurvature.FaceCutBelowTheDesignGetsItsOwnRasterDifferences
  DesignCurvature.ReducedTorusHasTheTorusCurvatureWhereRasterDifferencesSeeFacets
  GrindingSimulation.SweptBallSlotDoesNotDependOnTheSamplingStep
  PrestonRemoval.RemovedCrossSectionIsKpFVsOverVfForBallAndRoll
  ScallopPrediction.DefaultPrecisionBallOnPlaneMatchesExactScallop
  SimulationStage.PrestonWithNormalsAwayFromTheToolMatchesNoneAndThePrestonFormula
  SpacingRefinement.FlatWheelOnConvexCylinderIsLimitedByItsFormError
  SurfaceComparison.AllDeviationsOnUnresolvedFacesFailTheComparison
  # ddfcam_io_tests
  ConvertedEllipsoidMesh.GaussBonnetWithinTwoPercentAndIndicesSumToTwo
  ImportedPathShared.CrsToolZAxisPointsOutOfThePartAndAutoReadsItAsToolAxis
  Io/SharedPartsPipeline.*
  Readers/ReaderFuzz.MutatedInputsOnlyThrowErrorsWithValidLines/ros_yaml
  SpringbackCompensationShared.ModelIterationsFollowTheAlphaLaw
  SurfaceComparisonShared.DeviationMatchesSignedDistanceWhereSmall
  # ddfcam_io_cad_shared_tests
  CadCurvatureShared.DdfCurvatureOnStripTessellatedCylindersMatchesTheExactCurvature
  CadCurvatureShared.ReducedSupportCurvatureComesFromTheDesignMeshAndMatchesTheExactCurvature
  CadCurvatureShared.SphereCurvatureIsOneOverRadiusExactlyAndOnTheDdf
  CadPartShared.FacesUnitsAndBoundsAsTheFilesState
  Parts/CadPartFile.*/biquartic_sphere
  Parts/CadPartFile.*/bolt_clip
  Parts/CadPartFile.*/boxed_sphere
  Parts/CadPartFile.*/revolved_sphere
  # ddfcam_cli_tests
  Cli.DemoRunsTheBuiltInJob
  CliCompare.SharedFormingPair
  CliCoverage.PlungesThroughTheCrustReportClampedPoints
  CliCurvature.ReducedDdfKeepsItsMeshAndShowsItsCurvature
  CliPaths.BadOptionsAndNonPathFilesGiveClearErrors
  CliPaths.EverySharedPathFileConvertsToCsvAndAptAndReadsBack
  CliPaths.PathUnitsRotateAndTranslatePlaceLikeAPreparedFile
  CliPaths.SimulatingTheAptOfAPlanEqualsSimulatingItsCsv
  CliPlan.BunnyContactsLieOnThePart
  CliPlan.TurbineBladeContactsLieOnThePart
  CliRun.RefinedLinesMeetTheToleranceWithTheIsoScallopCount
  CliRun.RelativePathsResolveAgainstTheJobFile
  CliRun.SmallJobWritesOutputsThatReadBack
  CliRun.TwoRunsGiveIdenticalFiles
  CliSimulate.APathOfManyPosesIsAnnouncedWithItsEstimate
  CliSimulate.BadArgumentsGiveClearErrorsAndExitCodes
  CliSimulate.LeadTurnsAFlatEndIntoAnEllipticGroove
  CliSimulate.PlanThenSimulateOnTheDemoPart
  CliSimulate.ToolFromALibraryFileOnAStockMesh
  CliUnits.PlanAndCurvatureOnAMetreFileWithUnitsMMatchTheMillimetreFile
  # ddfcam_cli_shared_tests
  CliConvertCad.*
  SharedMeshes/CliConvertShared.*
  # GUI tests (one CTest test per Qt Test executable; *_dpr2 at twice the device pixels)
  ddfcam_batch_job_gui_tests
  ddfcam_error_map_panel_tests
  ddfcam_exe_screenshot
  ddfcam_exe_screenshot_unknown_field
  ddfcam_job_runner_tests
  ddfcam_main_window_tests
  ddfcam_menu_smoke_tests
  ddfcam_mould_panel_tests
  ddfcam_mould_tools_panel_tests
  ddfcam_part_curvature_tests
  ddfcam_part_import_tests
  ddfcam_part_scene_overlay_tests*
  ddfcam_part_scene_tests*
  ddfcam_path_export_tests
  ddfcam_path_import_tests
  ddfcam_segmentation_panel_tests
  ddfcam_shared_parts_gui_tests
  ddfcam_simulation_options_tests
  ddfcam_simulation_inspection_tests
  ddfcam_simulation_playback_tests
  ddfcam_spacing_refinement_panel_tests
  ddfcam_stale_fields_tests
  ddfcam_streamlines_panel_edit_tests
  ddfcam_streamlines_panel_methods_tests
  ddfcam_streamlines_panel_scallop_tests
  ddfcam_streamlines_panel_tests
  ddfcam_streamlines_placement_tests
  ddfcam_tools_panel_tests
  ddfcam_vtk_view_tests*
  ddfcam_workflow_tests
  # ddfcam-bench
  bench_smoke*
)

# Tests of executables that mix shared-data tests with others; executables that only test the
# shared parts (ddfcam_*_shared_tests) get `data` where they are registered.
set(DDFCAM_DATA_TESTS
  # ddfcam_ddf_tests
  DeformationSequence.SharedSpringbackPairLandsOnTheFormedPart
  MeshConversion.BunnyConvertsToAValidDdf
  # ddfcam_io_tests
  AptSharedFiles.*
  ImportedPathShared.*
  Io/SharedPartsPipeline.*
  MachinePostShared.*
  MeshIo/SharedMeshes.*
  PathFile/SharedAptFiles.*
  SharedPaths.*
  SpringbackCompensationShared.*
  SurfaceAlignmentShared.*
  SurfaceComparisonShared.*
  ToolPathCsv.ReadsTheSharedRoboticSandingPath
  # ddfcam_cli_tests
  CliCompare.SharedFormingPair
  CliPaths.EverySharedPathFileConvertsToCsvAndAptAndReadsBack
  CliPaths.MachineFileWritesTheHaasPostsAxesAndRefusesWhatDoesNotFit
  CliPaths.VariableAxisProgramAsFiveAxisGCodeIsAcceptedByRs274
  CliPlan.BunnyContactsLieOnThePart
  CliPlan.TurbineBladeContactsLieOnThePart
  # GUI tests
  ddfcam_mould_panel_tests
  ddfcam_part_import_tests
  ddfcam_path_import_tests
  ddfcam_shared_parts_gui_tests
)
