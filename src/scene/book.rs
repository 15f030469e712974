//! The numbers a book prints beside the construction that reproduces them: a scene's `book`
//! field. `graphostatik check` writes each as its own row under the checks: what the book
//! printed, what the construction gives, what the book's own inputs give (the check's closed
//! form), and whether they agree within what the printed number stands for; where they do
//! not, the cause the scene names (a rounding of the book, a slip, a drawing error, a model
//! the book simplifies).

use serde::{Deserialize, Serialize};

/// A number a book prints that a scene's construction stands for.
///
/// ```
/// use graphostatik::scene::BookValue;
/// let v: BookValue = serde_json::from_str(
///     r#"{"check": "piston acceleration b (Tolle’s parabola)", "at": "θ = 0°",
///         "printed": 181.5, "source": "LH B.3: p₀ = 181,5 m/s²"}"#,
/// ).unwrap();
/// assert_eq!(v.tolerance(), 0.05); // half a unit of the printed last place
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct BookValue {
    /// The check it stands beside, by the quantity the check table names
    /// (`"rod force S"`).
    pub check: String,
    /// The situation of that check as the check table's context column writes it
    /// (`"θ = 30°"`, `"dead load"`, `"dead load: joint I, member 1"`), where the quantity
    /// is checked in several; absent: the first check of that quantity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at: Option<String>,
    /// The number as the book prints it, in the check's unit.
    pub printed: f64,
    /// What the printed number stands for, ± in the check's unit; absent: half a unit of its
    /// last printed place (181.5 stands for ±0.05).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub within: Option<f64>,
    /// What `within` stands for where it is given (`"the books' drawing error of 3.5 %"`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub basis: Option<String>,
    /// Where the book prints it (`"LH B.3, S. 67: p₀ = 181,5 m/s²"`).
    pub source: String,
    /// Why the printed number and the construction differ by more than `within`, where they
    /// do: a rounding of the book, an arithmetic slip, a drawing error, another model input.
    /// A book value that differs with no cause given fails the check.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cause: Option<String>,
}

impl BookValue {
    /// What the printed number stands for: `within`, or half a unit of its last printed place.
    pub fn tolerance(&self) -> f64 {
        self.within.unwrap_or_else(|| {
            let text = format!("{}", self.printed);
            let places = text.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
            0.5 * 10f64.powi(-places)
        })
    }
}
