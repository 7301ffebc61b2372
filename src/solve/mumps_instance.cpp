#include "mumps_instance.h"

#include <fairsurf/mesh/errors.h>

namespace fairsurf::detail {

namespace {

std::string describe_error(int code) {
  switch (code) {
    case -6: return "structurally singular matrix";
    case -10: return "numerically singular matrix";
    case -13: return "out of memory";
    default: return is_workspace_error(code) ? "internal workspace too small" : "error";
  }
}

}  // namespace

MumpsSettings mumps_settings(const LinearSolverOptions& options, int communicator) {
  return {.communicator = communicator,
          .sym = options.symmetric ? 2 : 0,  // general symmetric (LDLᵀ with pivoting), or unsymmetric
          .ordering = options.ordering == FillOrdering::minimum_degree ? 6 : kNestedDissection,
          .name = to_string(options.kind),
          .controls = options.mumps_controls};
}

bool is_workspace_error(int code) {
  return code == -8 || code == -9 || code == -14 || code == -15 || code == -17 || code == -20;
}

std::string ordering_name(int code) {
  switch (code) {
    case 0: return "AMD";
    case 2: return "AMF";
    case 3: return "SCOTCH";
    case 4: return "PORD";
    case 5: return "METIS";
    case 6: return "QAMD";
    default: return "MUMPS ordering " + std::to_string(code);
  }
}

MumpsInstance::MumpsInstance(const MumpsSettings& settings)
    : name_(settings.name), ordering_(settings.ordering), ordering_given_(settings.controls.contains(7)) {
  id_.par = 1;
  id_.sym = settings.sym;
  id_.comm_fortran = settings.communicator;
  if (call(-1) < 0) {
    const int code = infog(1);
    call(-2);
    throw NumericalError("make_linear_solver: " + std::string(name_) + ": initialization failed (INFOG(1) = " +
                         std::to_string(code) + ")");
  }
  icntl(1) = -1;
  icntl(2) = -1;
  icntl(3) = -1;
  icntl(4) = 0;
  icntl(7) = settings.ordering;
  icntl(18) = 0;
  icntl(28) = 1;
  for (const auto& [k, value] : settings.controls) icntl(k) = value;
}

MumpsInstance::~MumpsInstance() { call(-2); }

void MumpsInstance::choose_ordering(int unknowns) {
  if (ordering_given_) return;
  const bool pord = ordering_ == kNestedDissection && unknowns > kLargestMinimumDegreeSystem;
  icntl(7) = pord ? 4 : ordering_;
}

int MumpsInstance::call(int job) {
  id_.job = job;
  dmumps_c(&id_);
  return infog(1);
}

void MumpsInstance::check(const char* phase) const {
  const int code = infog(1);
  if (code >= 0) return;
  throw NumericalError(std::string(phase) + ": " + name_ + ": " + describe_error(code) + " (INFOG(1) = " +
                       std::to_string(code) + ", INFOG(2) = " + std::to_string(infog(2)) + ")");
}

}  // namespace fairsurf::detail
