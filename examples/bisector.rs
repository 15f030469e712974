//! A construction of your own on a board: the perpendicular bisector of AB by ruler and
//! compass (Euclid I.10), every step recorded, checked and drawn. `cargo run --example bisector`
use graphostatik::prelude::*;

#[rustfmt::skip] // one ruler or compass step a line, as a construction protocol reads
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut b = Board::recording();
    let n = |caption: &'static str| Note::new(caption, Topic::Custom("bisector")).book("Euclid I.10");
    let (lbl, con) = (Label::plain, Role::Construction);
    let a = b.point(Point::new(0.0, 0.0), lbl("A"), Role::Given, n("point A"));
    let c = b.point(Point::new(80.0, 30.0), lbl("B"), Role::Given, n("point B"));
    let r = (c.g - a.g).norm();
    let ka = b.circle(&a, r, Drawn::Whole, Label::NONE, con, n("circle about A through B"))?;
    let kb = b.circle(&c, r, Drawn::Whole, Label::NONE, con, n("circle about B through A"))?;
    let p = b.cut_circle_circle(&ka, &kb, Branch::First, lbl("P"), n("the circles cut in P"))?;
    let q = b.cut_circle_circle(&ka, &kb, Branch::Second, lbl("Q"), n("and in Q"))?;
    let pq = b.line_through(&p, &q, lbl("m"), Role::Result, n("the bisector PQ"))?;
    let ab = b.line_through(&a, &c, Label::NONE, Role::Given, n("the line AB"))?;
    let m = b.meet_point(&pq, &ab, lbl("M"), n("PQ cuts AB in its midpoint M"))?;
    let am = b.measure(&a, &m, &ab, Scale::new(1.0, "mm"), Label::NONE, n("AM measured"));
    b.check(&am, "AM", "mm", "AM = AB/2", r, || r / 2.0);
    assert!(b.all_passed(), "every check passes");
    let out = std::env::temp_dir().join("bisector.svg");
    std::fs::write(&out, figure(&FigureMeta::titled("The perpendicular bisector"), &b, None))?;
    println!("{} steps, {} check(s), all passed: {}", b.steps().len(), b.checks().count(), out.display());
    Ok(())
}
