//! The other mechanisms of KG XIV beside the straight slider-crank ([`crate::crank`]), each a
//! procedure of ruler and compass on a [`Board`](crate::protocol::Board), checked against the
//! closed form of its loop.
//!
//! - [`scotch_yoke`]: the Kurbelschleife, KG Abb. 1069;
//! - [`slotted_link`]: the oscillating slotted link (quick return), KG Abb. 1071-1072;
//! - [`offset_crank`]: the offset (geschränkt) slider-crank, KG Abb. 1046;
//! - [`four_bar`]: the crank-rocker and the parallel crank, KG Abb. 1043, 1045.

pub mod four_bar;
pub mod offset_crank;
pub mod scotch_yoke;
pub mod slotted_link;
