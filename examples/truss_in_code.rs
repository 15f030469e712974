//! A truss built in code by the books' names, its Cremona plan drawn and checked (LH I B.4).
//! `cargo run --example truss_in_code`
use graphostatik::prelude::*;

#[rustfmt::skip] // the truss a line of joints, members and supports, as a book's table
fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A roof truss of 8 m span and 2 m rise, 1000 kg at each upper joint.
    let truss = Truss::builder()
        .joint("I", (0.0, 0.0)).joint("II", (4.0, 0.0)).joint("III", (8.0, 0.0))
        .joint("IV", (2.0, 1.0)).joint("V", (4.0, 2.0)).joint("VI", (6.0, 1.0))
        .member("1", "I", "IV").member("2", "IV", "V").member("3", "V", "VI")
        .member("4", "VI", "III").member("5", "I", "II").member("6", "II", "III")
        .member("7", "IV", "II").member("8", "V", "II").member("9", "VI", "II")
        .pin("I").roller("III", (0.0, 1.0))
        .build()?;
    let p = (0.0, -1000.0);
    let case = truss.load_case("dead load", &[("IV", p), ("V", p), ("VI", p)])?;
    let mut board = Board::recording();
    let results = truss.cremona(&mut board, &[case])?;
    assert!(board.all_passed(), "every member agrees with the joint equations");
    println!("{}", graphostatik::render::forces::markdown(&results, &[]));
    let out = std::env::temp_dir().join("truss_in_code.svg");
    std::fs::write(&out, figure(&FigureMeta::titled("A roof truss built in code"), &board, None))?;
    println!("{}", out.display());
    Ok(())
}
