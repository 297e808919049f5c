#pragma once
// Writing a run's figures into a directory: NAME.svg and NAME.csv for each (and NAME.png when
// asked), committed with the run's other outputs (files/atomic_file.h), all of them or none.

#include <string>
#include <vector>

#include "files/atomic_file.h"
#include "report/report.h"

namespace swarmlab::report {

/// Creates dir if needed and checks that files can be written there; returns a message
/// naming the problem, or "" when all is well. Called before a run, not after it.
std::string prepare_plot_dir(const std::string& dir);

/// Whether PNG output is possible here (it needs rsvg-convert, from Debian's librsvg2-bin).
std::string png_unavailable_reason();

/// Stages every figure's files (NAME.svg, NAME.csv, and NAME.png rendered from the staged SVG)
/// into files, for dir; they appear when files is committed, together with any other output.
/// Each SVG and CSV says what made it: made_by (provenance_lines, report/provenance.h).
std::string stage_figures(OutputFiles& files, const std::string& dir,
                          const std::vector<NamedFigure>& figures, bool png,
                          const std::vector<std::string>& made_by);

}  // namespace swarmlab::report
