// Private to the flow: the check of FlowOptions that every entry point of run_flow makes first.
#pragma once

#include <fairsurf/flow/flow.h>

namespace fairsurf::flow_detail {

/// Throws InvalidArgument ("run_flow: ...") naming the first option out of its range.
void check_options(const FlowOptions& o);

}  // namespace fairsurf::flow_detail
