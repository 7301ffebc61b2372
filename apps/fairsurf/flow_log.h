// JSON for flow reports: the per-step log of `smooth --log` (and the fill/fair/blend commands).
#pragma once

#include <fairsurf/flow.h>

#include <nlohmann/json.hpp>

namespace fairsurf::cli {

/// One trial step: E, τ, max|d|, max|V|, accepted/rejected and why, solver figures, phase times.
nlohmann::json to_json(const StepRecord& record);
/// The whole run: every step plus the summary figures (stop reason, time, energies, well-posedness).
nlohmann::json to_json(const FlowReport& report);

}  // namespace fairsurf::cli
