# Included by ctest after the discovered GoogleTest cases (CMakeLists.txt, TEST_INCLUDE_FILES):
# the longest cases get a COST, so ctest starts them first in a fresh build folder (which has no
# timings of its own yet) instead of in name order, where one of them could be left running
# alone at the end on an otherwise idle machine. Seconds on one core, 2026-11-30.
set_tests_properties(
  OptimalLapCommandTest.DarlingtonDiscLimitComparisonMeetsTheAcceptance  # 183
  RaceCommandTest.SpotChecksSolveTheOptimalLapFromTheFallOffsStates      # 46
  CoarseToFineTest.ReachesTheSameLapAsTheGuessStartInFewerIterations     # 38
  FeAbsEnsembleTest.FiguresAgreeAtTheFullAndHalfStepWithinTheirMargins   # 35
  LapSensitivitiesTest.MatchesTheCentralDifferenceOfTwoSolves            # 30
  PROPERTIES COST 100)
