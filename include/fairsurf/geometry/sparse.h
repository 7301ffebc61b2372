// fairsurf — the one sparse matrix type of the library: the operators (operators.h), the step
// matrices (flow.h) and the linear solvers (linear_solver.h) all hold it.
#pragma once

#include <Eigen/SparseCore>

namespace fairsurf {

/// Sparse matrix in compressed row storage: rows are vertices (or unknowns), as the operators are
/// assembled and as the solvers read them.
using SparseRowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

}  // namespace fairsurf
