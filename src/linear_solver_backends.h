// fairsurf — private: the back ends behind make_linear_solver (include/fairsurf/linear_solver.h).
#pragma once

#include <fairsurf/linear_solver.h>

#include <memory>
#include <string>

namespace fairsurf::detail {

/// Scientific notation without padding, for messages: 3.2e-4, 1e-10.
std::string short_scientific(double value);

std::unique_ptr<LinearSolver> make_mumps_solver(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> make_umfpack_solver(const LinearSolverOptions& options);
std::unique_ptr<LinearSolver> make_gmres_solver(const LinearSolverOptions& options);

}  // namespace fairsurf::detail
