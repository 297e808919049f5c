#pragma once
// The figures of an ensemble report (REPORT.json from swarmlab merge): the runs' mean P(t) and
// T(t) with their 95 % interval, and for expansions the stages' P and T against V.

#include <string>
#include <vector>

#include "report/figure.h"

namespace swarmlab::report {

inline constexpr const char* kEnsembleReportFormat = "swarmlab ensemble report";

struct EnsembleFigures {
  std::vector<NamedFigure> figures;
  std::string error;  ///< "" or what is wrong with the report
};

EnsembleFigures ensemble_figures(const std::string& report_text);

}  // namespace swarmlab::report
