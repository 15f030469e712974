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

/// The range of a scale's number (1 : n, or units per mm of sheet).
pub(super) const MIN_SCALE: f64 = 1e-9;
/// See [`MIN_SCALE`].
pub(super) const MAX_SCALE: f64 = 1e9;

/// Checks that every scale or pole given (`Some`) is a positive, finite number, and a scale
/// one within [`MIN_SCALE`]..=[`MAX_SCALE`].
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
            // A scale's number, 1 : n or so many units per mm: beyond this range one part of
            // a figure shrinks to nothing beside another (a force system at 1 : 1e308 drew
            // its forces and lost its positions to underflow: NaN moments).
            let scale = name.ends_with("scale") || name.contains("_per_mm");
            if scale && !(MIN_SCALE..=MAX_SCALE).contains(&v) {
                return Err(SceneError::Invalid {
                    origin: origin.to_string(),
                    field: name.to_string(),
                    message: format!(
                        "a scale must lie between {} and {}, got {}",
                        crate::fmt::sci(MIN_SCALE),
                        crate::fmt::sci(MAX_SCALE),
                        crate::fmt::sci(v)
                    ),
                });
            }
        }
    }
    Ok(())
}

/// The fields of one scene file, for errors that name them.
#[derive(Clone, Copy)]
pub(super) struct Fields<'a> {
    /// The file (the prefix of every error).
    pub(super) origin: &'a str,
}

impl Fields<'_> {
    /// A value that parses but is not allowed, at `field`.
    pub(super) fn bad(&self, field: &str, message: String) -> SceneError {
        SceneError::Invalid {
            origin: self.origin.to_string(),
            field: field.to_string(),
            message,
        }
    }

    /// `x` must be a finite number.
    pub(super) fn finite(&self, field: &str, x: f64) -> Result<(), SceneError> {
        if x.is_finite() {
            Ok(())
        } else {
            Err(self.bad(field, format!("must be a finite number, got {x}")))
        }
    }

    /// `x` must be a positive, finite length or number.
    pub(super) fn positive(&self, field: &str, x: f64) -> Result<(), SceneError> {
        if x.is_finite() && x > 0.0 {
            Ok(())
        } else {
            Err(self.bad(
                field,
                format!("must be a positive length or number, got {x}"),
            ))
        }
    }
}

/// The larger of a figure's extent by its lengths and by its forces (mm), with the scale field
/// that drives it.
pub(super) fn larger(by_length: f64, by_force: f64) -> (f64, &'static str) {
    if by_force > by_length || by_length.is_nan() {
        (by_force, "drawing.force_scale_kg_per_mm")
    } else {
        (by_length, "drawing.length_scale")
    }
}

/// The largest of a figure's extents (mm), each with the scale field that drives it, starting
/// from the extent by its lengths; a NaN extent wins, so that its field is named.
pub(super) fn largest(
    by_length: f64,
    others: impl IntoIterator<Item = (f64, &'static str)>,
) -> (f64, &'static str) {
    others
        .into_iter()
        .fold((by_length, "drawing.length_scale"), |best, x| {
            if x.0 > best.0 || x.0.is_nan() {
                x
            } else {
                best
            }
        })
}

/// Bytes a check needs per construction step where only its checks are kept: measured on a
/// beam of 1,000,000 loads (153 bytes a step, the table included) and a truss of 100,000
/// joints (253, the scene included), rounded up.
pub(super) const BYTES_PER_CHECKED_STEP: u64 = 256;

/// Whether a check of about `steps` construction steps fits in half the memory this machine
/// has free (where it can tell): the limit follows the machine, and the error names the
/// field that drives the count and says what it would take.
pub(super) fn check_fits_memory(
    origin: &str,
    field: &str,
    steps: usize,
    available: Option<u64>,
) -> Result<(), SceneError> {
    let need = (steps as u64).saturating_mul(BYTES_PER_CHECKED_STEP);
    match available {
        Some(free) if need > free / 2 => Err(SceneError::Invalid {
            origin: origin.to_string(),
            field: field.to_string(),
            message: format!(
                "about {steps} construction steps: checking them takes about {} MB, more \
                 than half of the {} MB this machine has free",
                need / 1_000_000,
                free / 1_000_000
            ),
        }),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_check_must_fit_in_half_the_free_memory() {
        let gb = 1u64 << 30;
        assert!(check_fits_memory("b.json", "point_loads", 1_000_000, Some(gb)).is_ok());
        let e = check_fits_memory("b.json", "point_loads", 18_000_000, Some(8 * gb))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("point_loads") && e.contains("4608 MB") && e.contains("8589 MB"),
            "{e}"
        );
        // Where the machine cannot tell, the fixed limits alone hold.
        assert!(check_fits_memory("b.json", "point_loads", usize::MAX, None).is_ok());
    }
}
