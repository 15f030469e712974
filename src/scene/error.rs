//! Errors in a scene, each naming the file and the field.

/// What is wrong with a scene. Every message names the file and, where there is one, the
/// field (`mechanism.rod.length_mm`) or the line and column.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SceneError {
    /// The file could not be read.
    #[error("{}: cannot read the scene: {}", one_line(.path), one_line(.message))]
    Io {
        /// The file.
        path: String,
        /// The operating system's words.
        message: String,
    },
    /// Malformed JSON, a missing or unknown field, a value of the wrong type.
    #[error("{}:{line}:{column}: {}{}", one_line(.origin), field_prefix(.field), one_line(.message))]
    Json {
        /// The file.
        origin: String,
        /// Line (1-based).
        line: usize,
        /// Column (1-based).
        column: usize,
        /// The path of the field (`mechanism.rod`), empty at the top level.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// A value that parses but makes no mechanism (a rod shorter than the crank, …).
    #[error("{}: {}{}", one_line(.origin), field_prefix(.field), one_line(.message))]
    Invalid {
        /// The file.
        origin: String,
        /// The path of the field.
        field: String,
        /// What is wrong, and why it matters.
        message: String,
    },
}

fn field_prefix(f: &str) -> String {
    if f.is_empty() {
        String::new()
    } else {
        format!("{}: ", one_line(f))
    }
}

/// A part of the message on one line: a scene's key or value may hold a newline (cargo fuzz
/// found `"title; …\n…"` as an unknown field, echoed raw by serde's message), which is
/// written escaped, as `\n`.
fn one_line(s: &str) -> String {
    crate::fmt::clip(s, usize::MAX)
}
