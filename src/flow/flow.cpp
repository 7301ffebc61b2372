#include "energy_descent.h"
#include "flow_failure.h"
#include "flow_options.h"
#include "flow_step.h"
#include "stopwatch.h"

#include <fairsurf/flow/flow.h>
#include <fairsurf/flow/orientation_guard.h>
#include <fairsurf/flow/tangential_relaxation.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/face_intersection.h>
#include <fairsurf/mesh/topology.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace fairsurf {
namespace {

using flow_detail::FlowProblem;
using flow_detail::FlowState;
using detail::Clock;
using detail::seconds_since;

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, fmt, a, b, c);
  return buffer;
}

// The map between the caller's coordinates and the flow's: x_flow = (x − centre) · scale.
struct Normalization {
  Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
  double scale = 1;
};

Normalization normalization(const Vertices& V, bool normalize) {
  Normalization n;
  if (!normalize || V.rows() == 0) return n;
  const Eigen::RowVector3d lo = V.colwise().minCoeff(), hi = V.colwise().maxCoeff();
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0)) throw InvalidMeshError("run_flow: the mesh's bounding box has zero diagonal");
  n.centre = 0.5 * (lo + hi);
  n.scale = 1.0 / diagonal;
  return n;
}

// Mean length of the edges at each vertex (#V).
Eigen::VectorXd local_edge_lengths(const Vertices& X, const Topology& topo) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(topo.num_vertices);
  for (int e = 0; e < topo.edges.rows(); ++e) {
    const int a = topo.edges(e, 0), b = topo.edges(e, 1);
    const double length = (X.row(a) - X.row(b)).norm();
    sum[a] += length, sum[b] += length;
  }
  for (int v = 0; v < topo.num_vertices; ++v)
    if (topo.vertex_vertices.size(v) > 0) sum[v] /= topo.vertex_vertices.size(v);
  return sum;
}

// The energy descent applies to the sixth-order flow only; the other flows step in time.
bool descends(const FlowOptions& options) {
  return options.step_kind == FlowStepKind::energy_descent && options.kind_to_run() == FlowKind::sixth_order;
}

// The energy descent's matrix N + diag(A)/(2τ) is symmetric: MUMPS factors it as LDLᵀ.
LinearSolverOptions step_solver_options(const FlowOptions& options) {
  LinearSolverOptions solver = options.solver;
  if (descends(options)) solver.symmetric = true;
  return solver;
}

// The run: the accepted state (positions X, with its normals, velocity and J) and the trial.
class FlowRun {
 public:
  FlowRun(Vertices& V, const Faces& F, const Topology& topo, const Region& region, const FlowOptions& options,
          const FlowObserver& observer)
      : V_(V), F_(F), region_(region), options_(options), observer_(observer), topo_(topo),
        solver_(make_linear_solver(step_solver_options(options))) {}

  FlowReport run();
  const WellPosedness& well_posedness() const { return report_.well_posedness; }

 private:
  void initialize();
  void accept_current_state();
  // One trial step at time step tau; returns true if accepted (record filled either way).
  bool try_step(double tau, StepRecord& record);
  bool solve_step(double tau, StepRecord& record, Eigen::VectorXd& d);
  void form_matrix(double tau);
  bool descending() const { return descends(options_); }
  int limit_displacement(Eigen::VectorXd& d) const;
  bool displacement_ok(const Eigen::VectorXd& d, StepRecord& record) const;
  bool faces_ok(StepRecord& record);
  bool crossings_ok(StepRecord& record);
  bool evaluate_trial(StepRecord& record);
  bool reject(StepRecord& record, StepRejection why, std::string detail);
  bool model_minimum_reached(int consecutive_rejections) const;
  void fail(const StepRecord& record, const std::string& what) const;
  void write_back() const;

  Vertices& V_;
  const Faces& F_;
  const Region& region_;
  const FlowOptions& options_;
  const FlowObserver& observer_;
  const Topology& topo_;  // the caller's: built once per mesh, not per run
  std::unique_ptr<LinearSolver> solver_;
  Eigen::Index analyzed_nonzeros_ = -1;

  Normalization norm_;
  FlowProblem problem_;
  FlowState state_;  // at the accepted positions, or at the last trial after one was evaluated
  flow_detail::JacobianWorkspace work_;
  FlowReport report_;
  double energy_floor_ = 0;
  std::vector<int> moving_faces_;  // faces with a free vertex
  bool guard_crossings_ = false;   // FlowOptions::reject_crossings, where the start does not cross

  // The accepted state's figures the next trial needs (the state itself is overwritten by a trial).
  Vertices X_, X_trial_;
  Vertices normal_;
  Eigen::VectorXd velocity_free_;  // τ-free right-hand side V_F
  Eigen::VectorXd edge_length_;
  Eigen::MatrixX3d face_direction_, face_direction_trial_;
  Eigen::MatrixX3d input_face_direction_;  // of the moving faces at the input
  double energy_ = 0;
  SparseRowMatrix jacobian_, step_matrix_;
  flow_detail::GaussNewtonModel model_;  // energy_descent's model in place of J
  Eigen::VectorXd damping_;  // what leaves J's diagonal in the step matrix (row_damping)
  bool jacobian_current_ = false;
  // The solver's factorization: valid, of I − τJ at this τ, accepted steps since it was made.
  bool factorized_ = false;
  double factorized_tau_ = 0;
  int factorization_age_ = 0;
  // Weight of the tangential relaxation of the next trial: scaled with τ by the step control, so
  // that a trial tends to x^k as rejections pile up.
  double relaxation_ = 0;
};

void FlowRun::initialize() {
  const int n = static_cast<int>(V_.rows());
  if (static_cast<int>(region_.free_index.size()) != n || region_.num_free() == 0)
    throw InvalidArgument("run_flow: the region has " + std::to_string(region_.free_index.size()) +
                          " vertices (" + std::to_string(region_.num_free()) +
                          " free) but the mesh has " + std::to_string(n));
  if (!V_.allFinite()) throw InvalidMeshError("run_flow: the mesh has a non-finite coordinate");
  norm_ = normalization(V_, options_.normalize);
  X_ = (V_.rowwise() - norm_.centre) * norm_.scale;
  report_.length_scale = norm_.scale;

  problem_.kind = options_.kind_to_run();
  problem_.curvature_resolution = options_.curvature_resolution;
  problem_.region = &region_;
  problem_.energy_weight.resize(n);
  for (int v = 0; v < n; ++v) problem_.energy_weight[v] = region_.ring[v] >= 0 ? 1.0 : 0.0;
  for (int f = 0; f < F_.rows(); ++f)
    if (region_.is_free(F_(f, 0)) || region_.is_free(F_(f, 1)) || region_.is_free(F_(f, 2)))
      moving_faces_.push_back(f);

  input_face_direction_ = face_directions(X_, F_, moving_faces_);
  guard_crossings_ = options_.step_control && options_.reject_crossings &&
                     find_face_intersections(X_, F_, moving_faces_, 1).empty();
  std::vector<int> fixed;  // FlowOptions::two_ring_boundary_fits
  if (options_.two_ring_boundary_fits)
    for (int v = 0; v < n; ++v)
      if (!region_.is_free(v)) fixed.push_back(v);
  flow_detail::initialize_geometry(X_, F_, topo_, options_.fit, fixed, state_);
  const SurfaceGeometry& geo = state_.ops.geometry;
  if (problem_.kind == FlowKind::sixth_order) {
    problem_.functions = parse_energy_functions(options_.functions);
    problem_.scale.curvature =
        options_.curvature_scale > 0 ? options_.curvature_scale : curvature_scale(geo.H, geo.K);
    problem_.scale.relative_epsilon = options_.relative_epsilon;
    report_.well_posedness = check_well_posedness(problem_.functions, geo.H, geo.K, problem_.scale);
  }
  report_.curvature_scale = problem_.scale.curvature;
  report_.free_vertices = region_.num_free();
  report_.step_kind = options_.step_kind;
  report_.supported = region_.supported;
  flow_detail::evaluate_flow_terms(problem_, state_);
  if (!std::isfinite(state_.energy) || !std::isfinite(state_.max_velocity))
    throw NumericalError("run_flow: the energy or velocity of the input is not finite");

  // Energy changes below the floor are round-off: 1e-12 of κ² Σ_l ∫ f_l² dA for the sixth order
  // (the size ‖∇f‖² would have if f varied on the curvature scale), of the energy itself otherwise.
  double energy_scale = state_.energy;
  if (problem_.kind == FlowKind::sixth_order) {
    energy_scale = 0;
    for (const EnergyTerms& t : state_.evaluation.terms)
      energy_scale += problem_.energy_weight.dot(geo.area.cwiseProduct(t.values.f.cwiseAbs2()));
    energy_scale *= problem_.scale.curvature * problem_.scale.curvature;
  }
  energy_floor_ = 1e-12 * energy_scale;
  report_.initial_energy = state_.energy;
  report_.initial_max_velocity = state_.max_velocity;
  accept_current_state();
}

// Copies from the state what later trials need; J is assembled lazily (not needed if we stop).
void FlowRun::accept_current_state() {
  normal_ = state_.ops.geometry.normal;
  velocity_free_.resize(region_.num_free());
  for (int k = 0; k < region_.num_free(); ++k)
    velocity_free_[k] = state_.velocity[region_.free_vertices[k]];
  edge_length_ = local_edge_lengths(X_, topo_);
  face_direction_ = face_directions(X_, F_, moving_faces_);
  energy_ = state_.energy;
  report_.final_energy = state_.energy;
  report_.final_max_velocity = state_.max_velocity;
  jacobian_current_ = false;
  ++factorization_age_;
}

void FlowRun::write_back() const {
  for (int v : region_.free_vertices) V_.row(v) = X_.row(v) / norm_.scale + norm_.centre;
}

void FlowRun::fail(const StepRecord& record, const std::string& what) const {
  throw NumericalError("run_flow: step " + std::to_string(record.step) + " (t = " +
                       format("%.6g, tau = %.3g", record.time, record.tau) + "): " + what);
}

bool FlowRun::reject(StepRecord& record, StepRejection why, std::string detail) {
  record.accepted = false;
  record.rejection = why;
  record.detail = std::move(detail);
  return false;
}

bool FlowRun::solve_step(double tau, StepRecord& record, Eigen::VectorXd& d) {
  const bool reuse =
      factorized_ && tau == factorized_tau_ && factorization_age_ < options_.refactor_interval;
  auto start = Clock::now();
  if (!reuse) {
    factorized_ = false;
    form_matrix(tau);
    record.assembly_seconds = seconds_since(start);
  }
  // The phase running, timed even if it fails.
  double* phase_seconds = reuse ? &record.solve_seconds : &record.factorize_seconds;
  start = Clock::now();
  try {
    if (!reuse) {
      if (step_matrix_.nonZeros() != analyzed_nonzeros_) {
        solver_->analyze(step_matrix_);
        analyzed_nonzeros_ = step_matrix_.nonZeros();
      }
      solver_->factorize(step_matrix_);
      record.factorize_seconds = seconds_since(start);
      record.refactorized = factorized_ = true;
      factorized_tau_ = tau;
      factorization_age_ = 0;
      phase_seconds = &record.solve_seconds;
      start = Clock::now();
    }
    d = descending() ? Eigen::VectorXd(solver_->solve(-model_.gradient)) : solver_->solve(tau * velocity_free_);
    record.solve_seconds = seconds_since(start);
  } catch (const NumericalError& e) {
    *phase_seconds = seconds_since(start);
    return reject(record, StepRejection::solver, e.what());
  }
  record.solver_iterations = solver_->report().iterations;
  record.backward_error = solver_->report().backward_error;
  if (!d.allFinite()) return reject(record, StepRejection::non_finite, "non-finite displacement");
  if (descending()) record.predicted_decrease = -(2 * model_.gradient.dot(d) + d.dot(model_.normal * d));
  record.max_displacement = d.cwiseAbs().maxCoeff();
  return true;
}

// The step matrix at τ: I − τ(J − diag(damping)) for the flow, N + diag(A)/(2τ) for the descent.
// J (or the model) is assembled once per accepted state.
void FlowRun::form_matrix(double tau) {
  if (!jacobian_current_) {
    if (descending()) {
      flow_detail::assemble_gauss_newton(problem_, state_, model_);
    } else {
      flow_detail::assemble_jacobian(problem_, state_, work_, jacobian_);
      // Without step control the step is the plain (I − τJ) d = τV of method.md §5.
      flow_detail::row_damping(jacobian_,
                               options_.step_control ? options_.jacobian_dominance
                                                     : -std::numeric_limits<double>::infinity(),
                               damping_);
    }
    jacobian_current_ = true;
  }
  if (descending())
    flow_detail::form_descent_matrix(model_, tau, step_matrix_);
  else
    flow_detail::form_step_matrix(jacobian_, damping_, tau, step_matrix_);
}

// Per-vertex trust region: |d_i| ≤ max_displacement_ratio · (mean edge length at i). Returns the
// number of vertices clipped.
int FlowRun::limit_displacement(Eigen::VectorXd& d) const {
  const double ratio = options_.max_displacement_ratio;
  int clipped = 0;
  for (int k = 0; k < region_.num_free(); ++k) {
    const double cap = ratio * edge_length_[region_.free_vertices[k]];
    clipped += std::abs(d[k]) > cap;
    d[k] = std::clamp(d[k], -cap, cap);
  }
  return clipped;
}

bool FlowRun::displacement_ok(const Eigen::VectorXd& d, StepRecord& record) const {
  const double ratio = options_.max_displacement_ratio;
  for (int k = 0; k < region_.num_free(); ++k) {
    const int v = region_.free_vertices[k];
    if (std::abs(d[k]) > ratio * edge_length_[v]) {
      record.rejection = StepRejection::displacement;
      record.detail = format("|d| %.3g > %.3g times the local edge length %.3g", std::abs(d[k]),
                             ratio, edge_length_[v]) + " at vertex " + std::to_string(v);
      return false;
    }
  }
  return true;
}

bool FlowRun::faces_ok(StepRecord& record) {
  face_direction_trial_ = face_directions(X_trial_, F_, moving_faces_);
  for (Eigen::Index k = 0; k < face_direction_trial_.rows(); ++k)
    if (!(face_direction_trial_.row(k).dot(face_direction_.row(k)) > 0))
      return reject(record, StepRejection::inverted_face,
                    "face " + std::to_string(moving_faces_[k]) + " inverted");
  return true;
}

bool FlowRun::crossings_ok(StepRecord& record) {
  if (!guard_crossings_) return true;
  const std::vector<FaceIntersection> crossings = find_face_intersections(X_trial_, F_, moving_faces_, 1);
  if (crossings.empty()) return true;
  return reject(record, StepRejection::crossing,
                "face " + std::to_string(crossings.front().query_face) + " crosses face " +
                    std::to_string(crossings.front().other_face));
}

bool FlowRun::evaluate_trial(StepRecord& record) {
  const auto start = Clock::now();
  try {
    flow_detail::update_geometry(X_trial_, state_);
    flow_detail::evaluate_flow_terms(problem_, state_);
  } catch (const NumericalError& e) {
    record.fit_seconds = seconds_since(start);
    return reject(record, StepRejection::non_finite, e.what());
  }
  record.fit_seconds = seconds_since(start);
  record.energy = state_.energy;
  record.max_velocity = state_.max_velocity;
  if (!std::isfinite(state_.energy) || !std::isfinite(state_.max_velocity))
    return reject(record, StepRejection::non_finite, "non-finite energy or velocity");
  return true;
}

bool FlowRun::try_step(double tau, StepRecord& record) {
  record.tau = tau;
  record.energy = std::numeric_limits<double>::quiet_NaN();
  record.max_velocity = std::numeric_limits<double>::quiet_NaN();
  const bool control = options_.step_control;
  Eigen::VectorXd d;
  if (!solve_step(tau, record, d)) return false;
  if (control && options_.limit_displacement) record.clipped_vertices = limit_displacement(d);
  if (control && !descending() && !displacement_ok(d, record)) return false;
  X_trial_ = X_;
  for (int k = 0; k < region_.num_free(); ++k) {
    const int v = region_.free_vertices[k];
    X_trial_.row(v) += d[k] * normal_.row(v);
  }
  relax_tangentially(X_trial_, topo_, region_.free_vertices, normal_, relaxation_);
  if (control && options_.hold_back_turned_faces) {
    const Eigen::MatrixX3d* const references[] = {&face_direction_, &input_face_direction_};
    record.held_back_vertices = hold_back_turned_faces(X_, X_trial_, F_, moving_faces_, references);
  }
  if (!faces_ok(record) || !crossings_ok(record) || !evaluate_trial(record)) return false;
  if (descending() && !(state_.energy < energy_))
    return reject(record, StepRejection::energy,
                  format("energy %.17g does not decrease from %.17g", state_.energy, energy_));
  const double growth = options_.max_energy_growth;
  if (control && state_.energy > growth * energy_ + energy_floor_)
    return reject(record, StepRejection::energy,
                  format("energy %.6g > %.3g times %.6g", state_.energy, growth, energy_));
  record.accepted = true;
  return true;
}

// energy_descent, after a rejection: whether the last two trials, both rejected because E rose,
// were promised the same decrease by the Gauss–Newton model (within 1%: shrinking τ no longer damps
// the step, which is the model's own minimum) and that decrease is below steady_energy_tolerance·E,
// or below a hundred times that and below what E rose by on both trials (the model's error there
// is larger than its promise: it no longer resolves a decrease). Then E has stopped decreasing.
// Without this test the rejections went on shrinking τ over a dozen orders of magnitude, each a
// factorization, until the damping finally bit and a step lowered E by a few 1e-7 of it
// (docs/flow.md, "Energy descent").
bool FlowRun::model_minimum_reached(int consecutive_rejections) const {
  const double tolerance = options_.steady_energy_tolerance;
  if (tolerance <= 0 || consecutive_rejections < 2 || report_.records.size() < 2) return false;
  const StepRecord& last = report_.records.back();
  const StepRecord& before = report_.records[report_.records.size() - 2];
  if (last.rejection != StepRejection::energy || before.rejection != StepRejection::energy) return false;
  const double promised = last.predicted_decrease, earlier = before.predicted_decrease;
  if (std::abs(promised - earlier) > 0.01 * std::abs(earlier)) return false;
  const double rise = std::min(last.energy, before.energy) - energy_;
  return promised < tolerance * energy_ || (promised < 100 * tolerance * energy_ && promised < rise);
}

FlowReport FlowRun::run() {
  initialize();
  const double tolerance = options_.steady_tolerance;
  double tau = options_.tau;
  relaxation_ = options_.tangential_relaxation;
  int consecutive_rejections = 0;
  const double relative = options_.steady_relative_tolerance * report_.initial_max_velocity;
  // energy_descent: the fraction of E the last accepted step removed (∞ before the first).
  double last_decrease = std::numeric_limits<double>::infinity();
  auto steady = [&] {
    return (tolerance > 0 && report_.final_max_velocity <= tolerance) ||
           (options_.steady_relative_tolerance > 0 && report_.final_max_velocity <= relative) ||
           (descending() && last_decrease < options_.steady_energy_tolerance);
  };
  auto finished = [&] {
    if (steady()) return report_.stop_reason = FlowStopReason::steady, true;
    if (options_.interrupted && options_.interrupted())
      return report_.stop_reason = FlowStopReason::interrupted, true;
    if (report_.time >= options_.end_time) return report_.stop_reason = FlowStopReason::end_time, true;
    if (report_.accepted_steps >= options_.max_steps)
      return report_.stop_reason = FlowStopReason::max_steps, true;
    return false;
  };
  while (!finished()) {
    StepRecord record;
    record.step = report_.accepted_steps + 1;
    record.attempt = static_cast<int>(report_.records.size()) + 1;
    record.time = report_.time;
    const double remaining = options_.end_time - report_.time;
    const double tau_try = std::min(tau, remaining);
    const bool accepted = try_step(tau_try, record);
    if (accepted &&
        state_.energy > options_.runaway_energy_factor * (report_.initial_energy + energy_floor_)) {
      record.accepted = false;
      report_.records.push_back(record);
      if (observer_) observer_(record);
      fail(record, format("the energy ran away to %.6g from %.6g", state_.energy,
                          report_.initial_energy));
    }
    if (accepted) {
      last_decrease = (energy_ - state_.energy) / energy_;
      X_.swap(X_trial_);
      report_.time = tau_try >= remaining ? options_.end_time : report_.time + tau_try;
      record.time = report_.time;
      ++report_.accepted_steps;
      consecutive_rejections = 0;
      accept_current_state();
      write_back();
      tau = std::min(options_.accept_factor * tau, options_.tau_max);
      relaxation_ = std::min(options_.accept_factor * relaxation_, options_.tangential_relaxation);
    } else {
      ++report_.rejected_steps;
      ++consecutive_rejections;
    }
    report_.records.push_back(record);
    if (observer_) observer_(record);
    if (accepted) continue;
    if (!options_.step_control)
      fail(record, std::string(to_string(record.rejection)) + " (step control is off): " + record.detail);
    if (descending() && model_minimum_reached(consecutive_rejections)) {
      report_.stop_reason = FlowStopReason::steady;
      break;
    }
    if (consecutive_rejections > options_.max_consecutive_rejections && descending()) {
      // No step lowers E any more, however small: E has stopped decreasing.
      report_.stop_reason = FlowStopReason::steady;
      break;
    }
    if (consecutive_rejections > options_.max_consecutive_rejections)
      fail(record, std::to_string(consecutive_rejections) +
                       " consecutive rejected steps; the last: " + to_string(record.rejection) +
                       ": " + record.detail);
    tau = tau_try * options_.reject_factor;
    relaxation_ *= options_.reject_factor;
  }
  report_.tau = tau;
  return report_;
}

}  // namespace

FlowReport run_flow(Vertices& V, const Faces& F, const Region& region, const FlowOptions& options,
                    const FlowObserver& observer) {
  flow_detail::check_options(options);  // before the faces, as always
  return run_flow(V, F, build_topology(F, static_cast<int>(V.rows())), region, options, observer);
}

FlowReport run_flow(Vertices& V, const Faces& F, const Topology& topo, const Region& region,
                    const FlowOptions& options, const FlowObserver& observer) {
  flow_detail::check_options(options);
  if (topo.num_vertices != V.rows() || topo.num_faces != F.rows())
    throw InvalidArgument("run_flow: the topology was built for another mesh");
  FlowRun run(V, F, topo, region, options, observer);
  try {
    return run.run();
  } catch (const NumericalError& e) {
    // The report, and with it the well-posedness, is lost with the throw: the error carries it, and
    // says it when f is not parabolic on part of the input, a likely cause of the failure.
    const WellPosedness& w = run.well_posedness();
    if (w.violating_vertices == 0) throw flow_detail::FlowFailure(e.what(), w);
    throw flow_detail::FlowFailure(std::string(e.what()) + " (f is not parabolic at " +
                                       std::to_string(w.violating_vertices) + " of " + std::to_string(w.vertices) +
                                       " vertices of the flow's input, method.md §4)",
                                   w);
  }
}

FlowReport run_flow(Vertices& V, const Faces& F, const FlowOptions& options,
                    const FlowObserver& observer) {
  flow_detail::check_options(options);
  const Topology topo = build_topology(F, static_cast<int>(V.rows()));
  const int rings = rings_needed(Continuity::G2);
  const std::vector<int> free = interior_vertices(topo, rings);
  if (free.empty())
    throw InvalidArgument("run_flow: no vertex is farther than " + std::to_string(rings) +
                          " rings from the mesh border; nothing can move");
  const Region region = make_region(topo, free, Continuity::G2);
  return run_flow(V, F, topo, region, options, observer);
}

}  // namespace fairsurf
