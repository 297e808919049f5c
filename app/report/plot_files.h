#pragma once
// Writing a run's figures into a directory: NAME.svg and NAME.csv for each (and NAME.png when
// asked), all of them or none, so a failed or interrupted report never leaves a partial set.

#include <string>
#include <vector>

#include "report.h"

namespace swarmlab::report {

/// Creates dir if needed and checks that files can be written there; returns a message
/// naming the problem, or "" when all is well. Called before a run, not after it.
std::string prepare_plot_dir(const std::string& dir);

/// Whether PNG output is possible here (it needs rsvg-convert, from Debian's librsvg2-bin).
std::string png_unavailable_reason();

/// Writes every figure into a hidden temporary directory inside dir, renders the PNGs there,
/// then moves the files into dir. On failure dir is left as it was and a message returned.
std::string write_figures(const std::string& dir, const std::vector<NamedFigure>& figures,
                          bool png);

}  // namespace swarmlab::report
