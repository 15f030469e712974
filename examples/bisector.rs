//! A construction of your own on a board: the perpendicular bisector of AB by ruler and
//! compass (Euclid I.10), every step recorded, checked and drawn. `cargo run --example bisector`
use graphostatik::prelude::*;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut b = Board::recording();
    let n = |caption| Note::new(caption, Topic::Custom("bisector")).book("Euclid I.10");
    let con = Role::Construction;
    let a = b.point(Point::new(0.0, 0.0), Role::Given.named("A"), n("point A"));
    let c = b.point(Point::new(80.0, 30.0), Role::Given.named("B"), n("point B"));
    let r = (c.g - a.g).norm();
    let ka = b.circle(&a, r, Drawn::Whole, con, n("circle about A through B"))?;
    let kb = b.circle(&c, r, Drawn::Whole, con, n("circle about B through A"))?;
    let p = b.cut_circle_circle(&ka, &kb, Branch::First, "P", n("the circles cut in P"))?;
    let q = b.cut_circle_circle(&ka, &kb, Branch::Second, "Q", n("and in Q"))?;
    let pq = b.line_through(&p, &q, Role::Result.named("m"), n("the bisector PQ"))?;
    let ab = b.line_through(&a, &c, Role::Given, n("the line AB"))?;
    let m = b.meet_point(&pq, &ab, "M", n("PQ cuts AB in its midpoint M"))?;
    let mm = Scale::new(1.0, "mm");
    let am = b.measure(&a, &m, &ab, mm, "AM", n("AM measured with the dividers"));
    b.check(&am, "AM", "mm", "AM = AB/2", r, || r / 2.0);
    assert!(b.all_passed(), "every check passes");
    let out = std::env::temp_dir().join("bisector.svg");
    let meta = FigureMeta::titled("The perpendicular bisector");
    std::fs::write(&out, figure(&meta, &b, None))?;
    let (steps, checks) = (b.steps().len(), b.checks().count());
    println!("{steps} steps, {checks} check(s) passed: {}", out.display());
    Ok(())
}
