// SPDX-License-Identifier: MIT
//! Why a command failed, and how that becomes one line on stderr and an exit code.

use std::fmt;
use std::io;
use std::process::ExitCode;

/// Exit code for bad input or a bad command line (clap's own usage errors use it too).
pub(crate) const EXIT_BAD_INPUT: u8 = 2;

/// Exit code when the result could not be written to stdout.
pub(crate) const EXIT_OUTPUT: u8 = 1;

/// A failed run of `hi`.
#[derive(Debug)]
pub(crate) enum Failure {
    /// The input (file, JSON or arguments) is unusable; the message names the problem.
    Input(String),
    /// Writing the result to stdout failed.
    Output(io::Error),
    /// Some scans of a batch (`hi fit --out-dir`) failed: the batch's output is still printed,
    /// and the exit status is that of bad input.
    Batch {
        /// The batch's output, for stdout.
        output: crate::output::Json,
        /// How many scans failed.
        failed: usize,
    },
}

impl Failure {
    /// A bad-input failure with this message.
    pub(crate) fn input(message: impl Into<String>) -> Self {
        Failure::Input(message.into())
    }

    /// The process exit code for this failure.
    pub(crate) fn exit_code(&self) -> ExitCode {
        match self {
            Failure::Input(_) | Failure::Batch { .. } => ExitCode::from(EXIT_BAD_INPUT),
            Failure::Output(_) => ExitCode::from(EXIT_OUTPUT),
        }
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::Input(message) => f.write_str(message),
            Failure::Output(e) => write!(f, "cannot write the output: {e}"),
            Failure::Batch { failed: 1, .. } => {
                f.write_str("1 scan failed (its error is in summary.jsonl)")
            }
            Failure::Batch { failed, .. } => {
                write!(f, "{failed} scans failed (their errors are in summary.jsonl)")
            }
        }
    }
}

impl From<hi_curve::Error> for Failure {
    fn from(e: hi_curve::Error) -> Self {
        Failure::Input(e.to_string())
    }
}

impl From<hi_surface::Error> for Failure {
    fn from(e: hi_surface::Error) -> Self {
        Failure::Input(e.to_string())
    }
}

impl From<hi_mesh::Error> for Failure {
    fn from(e: hi_mesh::Error) -> Self {
        Failure::Input(e.to_string())
    }
}

impl From<hi_compare::Error> for Failure {
    fn from(e: hi_compare::Error) -> Self {
        Failure::Input(e.to_string())
    }
}

/// Prefixes a library error with the argument or file it came from: `"--count: …"`.
pub(crate) fn context<E: fmt::Display>(what: &str) -> impl FnOnce(E) -> Failure + '_ {
    move |e| Failure::Input(format!("{what}: {e}"))
}

/// The line printed on stderr: `hi: ` and the message, on one line whatever the message holds.
pub(crate) fn stderr_line(message: &str) -> String {
    let flat: Vec<&str> =
        message.split(['\n', '\r']).map(str::trim).filter(|s| !s.is_empty()).collect();
    format!("hi: {}", flat.join(" "))
}

/// Flattens a clap usage error (several lines: message, possible values, tips, usage) into one
/// readable line that ends by pointing at the `--help` of `command` (such as `hi curve eval`).
pub(crate) fn flatten_clap_error(rendered: &str, command: &str) -> String {
    let mut out = String::new();
    let mut previous_indented = false;
    for line in rendered.lines() {
        let trimmed = line.trim();
        if trimmed.is_empty()
            || trimmed.starts_with("Usage:")
            || trimmed.starts_with("For more information")
        {
            continue;
        }
        let indented = line.starts_with(char::is_whitespace);
        let text = trimmed.strip_prefix("error:").map_or(trimmed, str::trim_start);
        if !out.is_empty() {
            let separator = if out.ends_with(':') {
                " "
            } else if indented && previous_indented {
                ", "
            } else {
                "; "
            };
            out.push_str(separator);
        }
        out.push_str(text);
        previous_indented = indented;
    }
    if out.is_empty() {
        format!("invalid command line (see '{command} --help')")
    } else {
        format!("{out} (see '{command} --help')")
    }
}

/// `message` about the file at `path`, led by the path unless it names the file already.
pub(crate) fn about_file(path: &std::path::Path, message: &str) -> String {
    let name = path.display().to_string();
    if message.contains(&name) { message.to_owned() } else { format!("{name}: {message}") }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clap_errors_become_one_line() {
        let rendered = "error: the following required arguments were not provided:\n  --k <K>\n  --t <T1,T2,...>\n\nUsage: hi basis --n <N> --k <K> --t <T1,T2,...>\n\nFor more information, try '--help'.\n";
        assert_eq!(
            flatten_clap_error(rendered, "hi basis"),
            "the following required arguments were not provided: --k <K>, --t <T1,T2,...> (see 'hi basis --help')"
        );
        let rendered = "error: invalid value 'foo' for '--variant <VARIANT>'\n  [possible values: thesis, nodes]\n\nFor more information, try '--help'.\n";
        assert_eq!(
            flatten_clap_error(rendered, "hi curve nonuniform"),
            "invalid value 'foo' for '--variant <VARIANT>'; [possible values: thesis, nodes] (see 'hi curve nonuniform --help')"
        );
    }

    #[test]
    fn messages_are_flattened() {
        assert_eq!(stderr_line("a\nb\r\n  c"), "hi: a b c");
    }
}
