# Included by ctest after the discovered tests (tests/CMakeLists.txt): the core tests that run the solver over
# campaign levels or the generator over seeds, three fifths of the core's test time, get the label "slow" beside
# "core". A change to the catalog does not reach them (campaign levels name their birds; the generator its own), so
# docs/extending.md's loop and its drill run `ctest -L core -LE slow`; every full run (tools/test, CI) runs them.
foreach(level IN ITEMS 1-8-from-the-cliff 4-7-hard-hats 4-8-cold-feet)
    set_tests_properties("Campaign/WhiteBirdLevels.TheEggIsTheSolversToolAndNothingElseWins/\"${level}\""
                         PROPERTIES LABELS "core;slow")
endforeach()
set_tests_properties(Generator.ALevelIsVerifiedAndTheSameSeedGivesTheSameBytesWhateverTheThreads
                     PROPERTIES LABELS "core;slow")
