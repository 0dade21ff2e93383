#pragma once
/// @file
/// report.html for tours (docs/report.md): each mode's flight record, targets and viewpoints,
/// the structure near the routes and, for both modes, the comparison table.

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/io/report_html.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <string>
#include <vector>

namespace ceilplan::io {

/// One mode's plan: the record on the tour's clock, the targets, a summary of its figures.
ReportPlan tourReportPlan(const mission::TourResult& tour);

/// The report of one or two modes (ceiling first) over `environment`'s map; with two, the
/// comparison rows of comparisonTable's main figures.
ReportModel tourReport(const std::vector<const mission::TourResult*>& tours, const mission::Mission& mission,
                       const environment::Environment& environment, const std::string& title);

}  // namespace ceilplan::io
