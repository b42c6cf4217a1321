// SPDX-License-Identifier: MIT
//! The libraries' errors as Python exceptions, each with the library's one-line message:
//! files that cannot be opened or written are `OSError`s (`FileNotFoundError`,
//! `PermissionError`, `IsADirectoryError` where the system says so), everything else about the
//! input is a `ValueError`.

use pyo3::PyErr;
use pyo3::exceptions::{
    PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyPermissionError, PyValueError,
};

/// A `ValueError` with `e`'s message.
pub(crate) fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// The `OSError` subclass for an I/O error of kind `kind`, with `message`.
fn os_error(kind: std::io::ErrorKind, message: String) -> PyErr {
    match kind {
        std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(message),
        std::io::ErrorKind::PermissionDenied => PyPermissionError::new_err(message),
        std::io::ErrorKind::IsADirectory => PyIsADirectoryError::new_err(message),
        _ => PyOSError::new_err(message),
    }
}

/// A `hi-fit` error as the exception a Python caller expects.
pub(crate) fn fit_error(e: hi_fit::Error) -> PyErr {
    let message = e.to_string();
    match e {
        hi_fit::Error::Open { source, .. } => os_error(source.kind(), message),
        hi_fit::Error::Write { .. } => PyOSError::new_err(message),
        _ => PyValueError::new_err(message),
    }
}
