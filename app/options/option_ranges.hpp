// The integer options' ranges: checked as the command line's text is read (cli/options.cpp), and
// again in prepare() for every platform.
#pragma once

namespace springlab::app {

struct WholeRange {
  double lo, hi;
};
inline constexpr WholeRange kSubsteps{1, 100000}, kSteps{1, 1e12}, kThreads{0, 1024},
    kIterations{1, 10000};

}  // namespace springlab::app
