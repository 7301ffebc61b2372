#include "flow_log.h"

namespace fairsurf::cli {

nlohmann::json to_json(const StepRecord& r) {
  nlohmann::json j{{"step", r.step},
                   {"attempt", r.attempt},
                   {"time", r.time},
                   {"tau", r.tau},
                   {"energy", r.energy},
                   {"max_displacement", r.max_displacement},
                   {"max_velocity", r.max_velocity},
                   {"accepted", r.accepted},
                   {"solver_iterations", r.solver_iterations},
                   {"backward_error", r.backward_error},
                   {"seconds",
                    {{"fit", r.fit_seconds},
                     {"assembly", r.assembly_seconds},
                     {"factorize", r.factorize_seconds},
                     {"solve", r.solve_seconds}}}};
  if (!r.accepted) j["rejection"] = {{"reason", to_string(r.rejection)}, {"detail", r.detail}};
  return j;
}

nlohmann::json to_json(const FlowReport& report) {
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& record : report.records) steps.push_back(to_json(record));
  return {{"stop_reason", to_string(report.stop_reason)},
          {"accepted_steps", report.accepted_steps},
          {"rejected_steps", report.rejected_steps},
          {"time", report.time},
          {"next_tau", report.tau},
          {"initial_energy", report.initial_energy},
          {"final_energy", report.final_energy},
          {"initial_max_velocity", report.initial_max_velocity},
          {"final_max_velocity", report.final_max_velocity},
          {"length_scale", report.length_scale},
          {"curvature_scale", report.curvature_scale},
          {"free_vertices", report.free_vertices},
          {"supported_continuity", std::string(to_string(report.supported))},
          {"well_posedness",
           {{"vertices", report.well_posedness.vertices},
            {"violating_vertices", report.well_posedness.violating_vertices}}},
          {"steps", steps}};
}

}  // namespace fairsurf::cli
