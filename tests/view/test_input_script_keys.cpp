// Input scripts: key names are bounded before they are turned into numbers.
#include <doctest/doctest.h>

#include "core/error.h"
#include "viewer/input_script.h"

TEST_CASE(
    "input script: a function key with a huge number is an error, not an exception of the "
    "library") {
  CHECK_THROWS_AS(throng::render::parseInputScript("key F12011111040 4\n", "keys.txt"),
                  throng::Error);
  CHECK_THROWS_AS(throng::render::parseInputScript("key F13 1\n", "keys.txt"), throng::Error);
  CHECK_NOTHROW(throng::render::parseInputScript("key F12 1\n", "keys.txt"));
}
