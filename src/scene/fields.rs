//! Helpers every scene's validation and figure share.

use super::error::SceneError;

/// The line under a figure's title: the book reference, then what the figure is drawn with.
pub(super) fn source_line(source: &str, detail: &str) -> String {
    if source.is_empty() {
        detail.to_string()
    } else {
        format!("{source} — {detail}")
    }
}

/// Checks that every scale or pole given (`Some`) is a positive, finite number.
pub(super) fn optional_positive(
    origin: &str,
    fields: &[(&str, Option<f64>)],
) -> Result<(), SceneError> {
    for &(name, v) in fields {
        if let Some(v) = v {
            if !(v.is_finite() && v > 0.0) {
                return Err(SceneError::Invalid {
                    origin: origin.to_string(),
                    field: name.to_string(),
                    message: format!("must be positive, got {v}"),
                });
            }
        }
    }
    Ok(())
}
