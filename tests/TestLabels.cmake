# The labels and timeouts of the GoogleTest cases; docs/DESIGN.md "Tests" says how to run each
# label. CTest reads this after the cases found in tetglow_tests (tetglow_tests_TESTS), each named
# Suite.Case (Instance/Suite.Case/parameter when parametrized). A name in a list below is a whole
# suite (no dot) or a regular expression for whole case names (with one). A case gets one kind:
#   cli     it runs the tetglow program (test::runTetglow, PreviewProcess, the preview server)
#   render  it drives the integrators in process: images, pixel estimates, photon passes
#   unit    neither (a case no list names is a unit test)
# and slow where it takes 2 s or more of processor time alone in a Release build, or tetrahedralizes
# the shared meshes (a slow unit case is slow only: `ctest -L unit` is the quick subset).
# Blender-driven cases add blender. TETGLOW_TIMEOUT_SCALE (set where this file is included)
# stretches the timeouts for sanitized builds.

set(cli_cases
  BadInput CommandLine CompareBoundaryCommand GenerateFormats InitCommand Loops Memory Messages
  OptionValues OutputFaults PbrtConvert PreviewCommand PreviewServer RegionsCommand RenderCommand
  RenderStops RepairNotes SceneLimits ScratchFolders GltfBlender
  CloudGenerator.CommandWritesTheCloud
  ExternalReferences.ConvertRefusesAModelThatReadsOutside
  "Farm.(DryRunPrintsTheJobsItWouldSubmit|HelpSaysWhatEachTaskGets|TakesTheOutputFromTheScene)"
  "Farm.(DefaultsTheOutputAsRenderDoes|RefusesWhatCannotBeSplit|RefusesValuesThatWouldBreakOutOfTheirLine)"
  "Farm.(QuotesPathsForBashAndForSbatch|ArrayOverTheLimitIsRefusedBeforeAnythingIsSubmitted)"
  "Farm.(FailedSbatchNamesTheCommandAndSuggestsDryRun|JobsSubmittedBeforeAFailedSubmissionAreCancelled)"
  "Farm.(PreambleAndSetupLinesRunFirstInEveryJob|CacheJobFailsWhenTheCacheCannotBeWritten)"
  Farm.WarnsAboutFoldersLocalToEachNode
  "GltfScene.(CameraFramingMatchesTheJsonCamera|LightsMatchJsonLightsAt683LumensPerWatt)"
  "GltfScene.(ConvertedToJsonRendersTheSameImage|PreviewSavesTheSceneAsJsonBesideIt|MalformedFilesAreOneLineErrors)"
  "GltfDraco.(BoxTetrahedralizesToItsVolumeAsAMeshFile|BoxSceneRendersAndTetrahedralizesToItsVolume)"
  "GltfDraco.(BrokenDataIsAOneLineErrorNamingTheFile|BrokenMeshFileIsAOneLineErrorNamingTheFile)"
  "Image.DiffCommand.*"
  "Init.(SceneRendersFromAnyFolder|CameraFramesTheMeshOnTheFloor)"
  InputFiles.DeeplyNestedJsonIsAnErrorNotACrash
  "InteriorRepair.Command.*"
  "MemoryEstimate.(MeshOverTheLimitIsRefusedWithItsEstimate|LimitMustBeANumberOfBytesWithinTheMachine)"
  MemoryEstimate.InstancingIsBoundedBeforeItIsFlattened
  "MeshFormats.(TetrahedralizeReadsBinaryPly|APlyElementWithoutPropertiesIsNotCountedThrough)"
  "MeshPrecision.(FarNodeIsNamed|AMeshTooSmallToRepresentSaysItsSize)"
  OutputLinks.InitRefusesAnOutputThatIsALinkToNothing
  "Outputs.(OutputThatNamesAnInputIsRefused|OutputThatNamesAFileTheSceneReadsIsRefused)"
  "Outputs.(OutputThatIsAFolderIsAnError|MissingFoldersAreCreatedTheSameWayByEveryCommand)"
  "PartialRender.(Merge(OfAnySplitIsTheRenderedFile|RefusesParts.*|MemoryDoesNotGrowWithTheParts))"
  "PartialRender.(RefusesTimeLimitsAndBadRanges|TurntableFramesSplitAndMerge)"
  "PolygonFaces.(APrismWithConcaveCapsTetrahedralizesToItsVolume|AFlatConcavePolygonIsRefusedInObjAsInCollada)"
  ReaderLeniency.TetrahedralizeTakesANodeAsSceneFilesDo
  "SceneRegions.(OverlappingMediaAreRefusedNamingBoth|CoincidentMediaAreRefused|AMediumCrossingItsContainerIsRefused)"
  "SceneRegions.(NestedMediaRenderAsOneTetMesh|TouchingMediaRenderAsOneTetMesh|ACavityRendersInsideItsMedium)"
  "SceneRegions.(ACavityInNoMediumIsRefused|AnOpenInnerMeshIsRepairedOrWhenStrictRefusedNamingIt|MediaApartStillRender)"
  "Slab.(LargestPhotonCountEndsAtItsTimeLimit|LongRunPrintsProgressAndTimeLeft|CommandPrintsJsonAndRejectsBadParameters)"
  "StabilityRender.(BrokenMediaAreRefusedWhenStrict|SmallHolesRenderLikeTheClosedMesh)")

set(render_cases
  Render NestedRender DensePhoton Emitters LiveRender Light SurfaceInsideAMedium Retune StabilityRender
  "Photon.(EnergyBalance|EstimatesAgreeWithVolpathAndEachOther|FinalGatherTakesAFloorsIndirectLightWithoutBlur)"
  "Photon.(APassPastItsDeadlineTracesOneBlockAtFullPower|CausticPhotonsCameFromALightBySpecularEventsOnly)"
  "Photon.(StoredPhotonsAreBoundedNotOnePerPath|DefaultAlphaBalancesBiasAndVariance)"
  "NoiseEstimate.(IndependentHalvesEstimateTheErrorWithoutBias|NoiseTargetStopsAtTheSamePassOnAnyThreadCount)"
  Sampler.ImagesKeepTheirMean
  LightSelection.VolpathDirectLightOnAFloorMatchesClosedForm
  PartialRender.MergedFilmsAreTheSingleRenderBitForBit
  "Slab.(MatchesPublishedReflectanceAndTransmittance|NoScatteringGivesBeerLambert|SameResultAnyThreadCount)"
  Slab.PhotonAtTheEventCapIsAnError)

# 2 s or more of processor time alone (Release), whatever the kind, and every case on the shared
# meshes (blub, spot, bob), which tetrahedralizes them without the cache.
set(slow_cases
  "StabilityRender.RaysThroughVerticesEdgesAndGrazing.*"
  NoiseEstimate.IndependentHalvesEstimateTheErrorWithoutBias
  "Photon.(FinalGatherTakesAFloorsIndirectLightWithoutBlur|EstimatesAgreeWithVolpathAndEachOther)"
  "NestedRender.(VolpathAndPhotonMappingAgreeOnNestedScatteringMedia|TransmittanceThroughNestedSpheresAndACavityIsTheClosedForm)"
  Render.SingleScatteringBoundaryModes
  Render.SameSeedSameImageAnyThreadCount
  DensePhoton.AgreesWithVolpath
  Light.PhotonsDepositTheIrradianceThatSampleGives
  "PartialRender.(MergeMemoryDoesNotGrowWithTheParts|MergeOfAnySplitIsTheRenderedFile)"
  OutputFaults.CtrlCWhileTheExrIsWrittenKeepsTheImageAndNoTemporary
  RenderCommand.CtrlCStillWritesTheImage
  Slab.LongRunPrintsProgressAndTimeLeft
  "PreviewServer.(AStopAsSoonAsTheURLIsPrintedEndsTheServer|SlowClientsLeaveThreadsForOthers)"
  GltfBlender
  "RegionWalk.TransmittanceThroughNestedSpheresIsTheClosedForm"
  InteriorRepair.SharedMeshesWithHoles
  Stability.SliverTets
  FuzzFindings.ColladaIndexListThatNeverEndsStopsAtTheImportsLimits
  "TetCore.*/(blub|spot|bob)"
  "TetCore.(RandomRayChordsMatchEmbree|DegenerateRayChordsMatchEmbreeOrExactChord)/fish"
  RegionWalk.PointsAreLocatedInTheirRegionAcrossInterfaces
  "RegionExitInReferenceMesh.*/(blub|spot|bob)")

set(blender_cases GltfBlender)

# Timeouts in seconds: many times what the slowest case of each kind takes alone (under 2 s for a
# unit case, half a minute for a slow one), for a machine shared with other jobs.
set(unit_timeout 60)
set(cli_timeout 120)
set(render_timeout 300)
set(slow_timeout 600)
if(NOT TETGLOW_TIMEOUT_SCALE)
  set(TETGLOW_TIMEOUT_SCALE 1)
endif()

# Per list: its whole suites (${list}_suites), and per suite the patterns for its cases
# (${list}_cases_in_<suite>). CMake's expressions hold at most nine groups, so each is tried alone.
foreach(list IN ITEMS cli render slow blender)
  set(${list}_suites "")
  foreach(name IN LISTS ${list}_cases)
    if(name MATCHES "^([A-Za-z0-9_]+)[.]")
      list(APPEND ${list}_cases_in_${CMAKE_MATCH_1} "${name}")
    else()
      list(APPEND ${list}_suites "${name}")
    endif()
  endforeach()
endforeach()

# Whether list `list` names `case` of `suite`.
macro(tetglow_names list suite case result)
  set(${result} FALSE)
  list(FIND ${list}_suites "${suite}" index)
  if(index GREATER -1)
    set(${result} TRUE)
  else()
    foreach(pattern IN LISTS ${list}_cases_in_${suite})
      if("${case}" MATCHES "^${pattern}$")
        set(${result} TRUE)
        break()
      endif()
    endforeach()
  endif()
endmacro()

set(all_cases "")
foreach(test IN LISTS tetglow_tests_TESTS)
  # "Meshes/TetCore.VolumeMatchesSurface/blub  # GetParam() = blub" is the case
  # TetCore.VolumeMatchesSurface/blub of the suite TetCore.
  if(NOT test MATCHES "^([A-Za-z0-9_]+/)?(([A-Za-z0-9_]+)[.][A-Za-z0-9_]+(/[A-Za-z0-9_]+)?)")
    message(FATAL_ERROR "tests/TestLabels.cmake: cannot read the test name '${test}'")
  endif()
  set(case ${CMAKE_MATCH_2})
  set(suite ${CMAKE_MATCH_3})
  list(APPEND all_cases ${case})
  tetglow_names(cli ${suite} ${case} cli)
  tetglow_names(render ${suite} ${case} render)
  tetglow_names(slow ${suite} ${case} slow)
  tetglow_names(blender ${suite} ${case} blender)
  if(cli)
    set(kind cli)
  elseif(render)
    set(kind render)
  else()
    set(kind unit)
  endif()
  set(labels ${kind})
  if(slow)
    list(REMOVE_ITEM labels unit)
    list(APPEND labels slow)
    set(kind slow)
  endif()
  if(blender)
    list(APPEND labels blender)
  endif()
  math(EXPR timeout "${${kind}_timeout} * ${TETGLOW_TIMEOUT_SCALE}")
  set_tests_properties("${test}" PROPERTIES LABELS "${labels}" TIMEOUT ${timeout})
endforeach()

# A name that no longer names a case (renamed, removed) would leave its cases unit tests unseen.
if(all_cases)
  foreach(list IN ITEMS cli render slow blender)
    foreach(name IN LISTS ${list}_cases)
      if(name MATCHES "[.]")
        set(pattern "(^|;)${name}(;|$)")
      else()
        set(pattern "(^|;)${name}[.]")
      endif()
      if(NOT all_cases MATCHES "${pattern}")
        message(FATAL_ERROR "tests/TestLabels.cmake: ${name} in ${list}_cases names no test case")
      endif()
    endforeach()
  endforeach()
endif()
