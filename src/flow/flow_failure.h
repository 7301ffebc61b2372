// Private to the library: the error run_flow throws when a flow fails, carrying what its report
// (lost with the throw) would have said about the flow's input.
#pragma once

#include <fairsurf/flow/flow.h>
#include <fairsurf/mesh/errors.h>

#include <string>

namespace fairsurf::flow_detail {

/// A NumericalError with the well-posedness of the failed flow's input, so that fair_region can
/// keep it in its report when it falls back to the linear solution (fill's per-hole warning and
/// its held-out check would otherwise lose it exactly when f is the likely cause).
class FlowFailure : public NumericalError {
 public:
  FlowFailure(const std::string& what, const WellPosedness& w) : NumericalError(what), well_posedness(w) {}
  WellPosedness well_posedness;
};

}  // namespace fairsurf::flow_detail
