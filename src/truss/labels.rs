//! How the truss drawing and the plan name things: the scene's names for joints, members
//! and supports, and the letters of Bow's spaces.

use super::Truss;
use crate::protocol::{Board, Label};

/// Letters of the spaces in Bow's notation; further spaces are r₂₇, r₂₈, ….
const SPACE_NAMES: [&str; 26] = [
    "a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m", "n", "o", "p", "q", "r", "s",
    "t", "u", "v", "w", "x", "y", "z",
];

pub(super) fn space_label(i: usize) -> Label {
    if i < SPACE_NAMES.len() {
        Label::plain(SPACE_NAMES[i])
    } else {
        Label::indexed("r", i as u32 + 1)
    }
}

/// A member's label: `S` with its number where the scene numbers its members as the books do
/// (`"7"` is S₇), else the scene's own name (`"U1"` is U₁, see [`Label::from_name`]); none
/// on a board that does not keep its drawing (nothing would write it).
pub(crate) fn member_label(b: &Board, t: &Truss, m: usize) -> Label {
    if !b.is_drawing() {
        return Label::NONE;
    }
    let name = &t.members[m].name;
    match name.parse::<u32>() {
        Ok(n) => Label::indexed("S", n),
        Err(_) => Label::from_name(name),
    }
}

/// A member's number as the truss drawing letters it (LH Abb. 17: members in Arabic
/// numbers, joints in Roman numerals): the scene's name for it (`"7"`, or `"U1"` as U₁);
/// none on a board that does not keep its drawing.
pub(crate) fn member_number(b: &Board, t: &Truss, m: usize) -> Label {
    if !b.is_drawing() {
        return Label::NONE;
    }
    Label::from_name(&t.members[m].name)
}

/// A member as a step's situation or a check's object names it ("member 5"), written into
/// the board's buffer ([`Board::naming`], [`Board::checking`]).
pub(crate) fn write_member(t: &Truss, m: usize) -> impl FnOnce(&mut String) + '_ {
    move |s| {
        s.push_str("member ");
        s.push_str(&t.members[m].name);
    }
}

/// A joint's label: the scene's name for it (the books' Roman numerals, or any other; see
/// [`Label::from_name`]); none on a board that does not keep its drawing.
pub(super) fn joint_label(b: &Board, t: &Truss, j: usize) -> Label {
    // Only a drawing shows it (as `member_label`): a check names its joint by its context.
    if !b.is_drawing() {
        return Label::NONE;
    }
    Label::from_name(&t.joints[j].name)
}

/// A support's label: the scene's name for its reaction (A, B, … by default).
pub(super) fn support_label(t: &Truss, si: usize) -> Label {
    Label::from_name(&t.supports[si].name)
}
