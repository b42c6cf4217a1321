// SPDX-License-Identifier: MIT
//! The errors of a fit run as a program runs it: each names the scan or file it is about.

use std::fmt;
use std::path::PathBuf;

/// Why fitting a scan, or a batch of scans, stopped; `Display` is one line naming the scan or
/// file and the problem.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// The scan file could not be opened (missing, a folder, no permission).
    Open {
        /// The scan.
        path: PathBuf,
        /// The system's error.
        source: std::io::Error,
    },
    /// The scan could not be read: its format is unknown or its contents are malformed.
    Read {
        /// The scan.
        path: PathBuf,
        /// What `hi-scan` found (with the line or byte).
        source: hi_scan::Error,
    },
    /// The fit failed on this scan.
    Fit {
        /// The scan, as named by the caller.
        scan: String,
        /// What went wrong.
        source: hi_geomimage::Error,
    },
    /// An output could not be written.
    Write {
        /// The file.
        path: PathBuf,
        /// Why.
        message: String,
    },
    /// The request itself is unusable (an unknown output format, two scans of one name, a
    /// folder that cannot be made).
    Input(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Open { path, source } => write!(f, "cannot read {}: {source}", path.display()),
            Self::Read { path, source } => {
                let name = path.display().to_string();
                let message = source.to_string();
                if message.contains(&name) {
                    f.write_str(&message)
                } else {
                    write!(f, "{name}: {message}")
                }
            }
            Self::Fit { scan, source } => write!(f, "{scan}: {source}"),
            Self::Write { path, message } => {
                write!(f, "{}: cannot write: {message}", path.display())
            }
            Self::Input(message) => f.write_str(message),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Open { source, .. } => Some(source),
            Self::Read { source, .. } => Some(source),
            Self::Fit { source, .. } => Some(source),
            Self::Write { .. } | Self::Input(_) => None,
        }
    }
}
