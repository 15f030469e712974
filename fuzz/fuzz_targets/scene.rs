//! The scene parser and everything after it: any text is either refused with one line naming
//! the place, or constructs (or is refused by the construction naming its step) with every
//! checked number finite, its check table and figure written without a panic.
#![no_main]

use graphostatik::protocol::BoardConfig;
use graphostatik::scene::AnyScene;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let scene = match AnyScene::from_json(text, "fuzz.json") {
        Ok(s) => s,
        Err(e) => {
            assert!(
                !e.to_string().contains('\n'),
                "error of more than one line: {e}"
            );
            return;
        }
    };
    let problem = scene.problem();
    let Ok(board) = problem.construct(BoardConfig::DRAWING) else {
        return;
    };
    for c in board.checks() {
        assert!(
            c.constructed.is_finite() && c.closed_form.is_finite() && c.error.is_finite(),
            "{}: {} against {}",
            c.quantity,
            c.constructed,
            c.closed_form
        );
    }
    let _ = graphostatik::render::check_table_text(&board);
    let svg = graphostatik::render::figure(&problem.figure_meta(), &board, None);
    // The geometry's attributes hold no NaN or inf (text may: a title can say "-inf").
    let geometry = [
        " d=\"",
        " points=\"",
        " x=\"",
        " y=\"",
        " cx=\"",
        " cy=\"",
        " r=\"",
        " x1=\"",
        " y1=\"",
        " x2=\"",
        " y2=\"",
        " width=\"",
        " height=\"",
        " viewBox=\"",
        " transform=\"",
    ];
    let bad = geometry.iter().any(|attr| {
        svg.split(attr).skip(1).any(|rest| {
            let value = rest.split('"').next().unwrap_or("");
            value.contains("NaN") || value.contains("inf")
        })
    });
    assert!(!bad, "a figure with a NaN or inf");
});
