// fairsurf — typed exceptions.
//
// The library never prints. Every failure is thrown as one of these types, and every message starts
// with the name of the function that detected it ("read_mesh: ..."), so a user can tell what failed
// and where without a stack trace. The CLI maps each type to one documented exit code
// (docs/cli.md).
#pragma once

#include <stdexcept>
#include <string>

namespace fairsurf {

/// Base class of every exception the library throws.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// A caller passed an invalid option or argument (negative time step, unknown name, ...).
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

/// A file could not be opened, read or written, or its extension is not a supported format.
class IoError : public Error {
 public:
  using Error::Error;
};

/// A file was opened but its content is malformed or truncated; the message says where it broke.
class ParseError : public IoError {
 public:
  using IoError::IoError;
};

/// The mesh violates a requirement of the operation (non-manifold, degenerate, NaN, ...).
class InvalidMeshError : public Error {
 public:
  using Error::Error;
};

/// The mesh violates a requirement, and every violation is one `repair` (repair.h) removes:
/// non-manifold edges or vertices, inconsistent orientation, degenerate, duplicate or invalid faces
/// (thrown by require_valid, validate.h).
class RepairableMeshError : public InvalidMeshError {
 public:
  using InvalidMeshError::InvalidMeshError;
};

/// A numerical computation failed: an ill-posed fit, a diverging flow, a failed linear solve.
class NumericalError : public Error {
 public:
  using Error::Error;
};

}  // namespace fairsurf
