//! The graphostatik engine for the browser: `graphostatik::web::replay_kept` behind a C ABI,
//! so that the page needs no generated glue (`site/engine.js` calls these functions).
//!
//! The page copies the scene's name and text into buffers it asks [`gs_alloc`] for, calls
//! [`gs_replay`] and reads the answer (JSON, UTF-8) at [`gs_out_ptr`] for the length
//! `gs_replay` returned, and the figure (SVG, apart from the JSON) at [`gs_svg_ptr`] for
//! [`gs_svg_len`] bytes. The engine keeps the last figure it drew, numbered
//! ([`gs_figure_id`]); a page that shows that figure says so, and reads what changed from it
//! (`graphostatik::web::figure_patch`, JSON) at [`gs_patch_ptr`] for [`gs_patch_len`] bytes
//! instead of the whole figure. It keeps the last construction too: the answer when the
//! pointer rests lists the steps without any page's details, which the page reads page by
//! page with [`gs_details`] at [`gs_details_ptr`]. A panic cannot unwind out of WebAssembly:
//! it traps, after the hook below has kept its message, which the page reads with
//! [`gs_panic_ptr`] and [`gs_panic_len`] before it starts a fresh instance. Nothing here
//! uses threads, clocks or files.

use graphostatik::web::Ask;
use std::cell::RefCell;

thread_local! {
    /// The last answer, kept until the next call.
    static OUT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    /// The last figure drawn (SVG; a refused scene draws none), kept until the next, with
    /// its lines read for the next patch.
    static SVG: RefCell<(String, graphostatik::web::FigureLines)> = RefCell::new(Default::default());
    /// The number of figures drawn: the last one's number.
    static FIGURE: std::cell::Cell<u32> = const { std::cell::Cell::new(0) };
    /// What changed from figure `base` to the last one (JSON; empty: ask for the figure).
    static PATCH: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    /// The construction of the last scene built, for the details of its pages.
    static KEPT: RefCell<Option<graphostatik::web::Kept>> = const { RefCell::new(None) };
    /// The last page's details asked for ([`gs_details`]).
    static DETAILS: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    /// The message of a panic, kept for the page.
    static PANIC: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
}

/// A buffer of `len` bytes for the page to write into; it is freed by the call it is passed
/// to.
#[no_mangle]
pub extern "C" fn gs_alloc(len: usize) -> *mut u8 {
    let mut v = Vec::<u8>::with_capacity(len.max(1));
    let p = v.as_mut_ptr();
    std::mem::forget(v);
    p
}

/// Takes back a buffer of [`gs_alloc`] that was not passed to [`gs_replay`].
///
/// # Safety
/// `ptr` and `len` are a buffer [`gs_alloc`] returned for `len` bytes, not freed since.
#[no_mangle]
pub unsafe extern "C" fn gs_free(ptr: *mut u8, len: usize) {
    drop(Vec::from_raw_parts(ptr, 0, len.max(1)));
}

/// Replays the scene `text` (named `name` in errors): both buffers of [`gs_alloc`] filled
/// with UTF-8, and freed here. `page` below 0 asks for the answer when the pointer rests,
/// the step list's lines without any page's details (`graphostatik::web::Ask::Lines`;
/// [`gs_details`] gives a page's), else for the answer of a drag on that page
/// (`graphostatik::web::Ask::Page`). The construction is kept for [`gs_details`] until the
/// next scene that is built, and where the same scene is asked for again (the pointer
/// released after a drag) the answer is made from it: nothing is constructed or drawn, the
/// figure is the last one and keeps its number (`graphostatik::web::replay_into`). `base` is the number of the figure the page shows
/// ([`gs_figure_id`]; below 0: none of this engine's): where it is the last figure drawn,
/// what changed from it is put at [`gs_patch_ptr`]. Returns the length of the JSON answer at
/// [`gs_out_ptr`].
///
/// # Safety
/// Each pointer and length is a buffer [`gs_alloc`] returned for that many bytes, all
/// written.
#[no_mangle]
pub unsafe extern "C" fn gs_replay(
    name: *mut u8,
    name_len: usize,
    text: *mut u8,
    text_len: usize,
    page: i32,
    base: i32,
) -> usize {
    install_hook();
    PATCH.with(|p| p.borrow_mut().clear());
    let name = Vec::from_raw_parts(name, name_len, name_len.max(1));
    let text = Vec::from_raw_parts(text, text_len, text_len.max(1));
    let name = String::from_utf8_lossy(&name).into_owned();
    let answer = match std::str::from_utf8(&text) {
        Ok(t) => {
            let ask = usize::try_from(page).map_or(Ask::Lines, Ask::Page);
            let (json, svg) =
                KEPT.with(|k| graphostatik::web::replay_into(&mut k.borrow_mut(), t, &name, ask));
            match svg {
                Some(svg) if !svg.is_empty() => keep_figure(svg, base),
                Some(_) => {}
                None => same_figure(base),
            }
            json
        }
        Err(e) => {
            // The byte offset of the first invalid byte, as a line and column.
            let before = &text[..e.valid_up_to()];
            let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
            let col = before.len()
                - before
                    .iter()
                    .rposition(|&b| b == b'\n')
                    .map_or(0, |i| i + 1)
                + 1;
            let error = format!("{name}:{line}:{col}: the scene is not UTF-8 text");
            format!("{{\"ok\":false,\"error\":{}}}", json_string(&error))
        }
    };
    OUT.with(|o| {
        let mut o = o.borrow_mut();
        *o = answer.into_bytes();
        o.len()
    })
}

/// Keeps `svg` as the last figure, numbered anew; where the page shows the figure it follows
/// (`base`), what changed from that one is kept for the page.
fn keep_figure(svg: String, base: i32) {
    let id = FIGURE.with(|f| f.get());
    let read = graphostatik::web::FigureLines::of(&svg);
    SVG.with(|o| {
        let mut o = o.borrow_mut();
        if u32::try_from(base) == Ok(id) && !o.0.is_empty() {
            let (old, read_old) = &*o;
            if let Some(p) = graphostatik::web::figure_patch_read(old, read_old, &svg, &read) {
                PATCH.with(|b| *b.borrow_mut() = p.to_json().into_bytes());
            }
        }
        *o = (svg, read);
    });
    FIGURE.with(|f| f.set(id % ((1 << 30) - 1) + 1));
}

/// The last figure drawn is the figure again (its scene was asked for once more): where the
/// page shows it (`base`), the patch says that nothing changed; its number stays.
fn same_figure(base: i32) {
    let id = FIGURE.with(|f| f.get());
    if u32::try_from(base) == Ok(id) && SVG.with(|o| !o.borrow().0.is_empty()) {
        let none = graphostatik::web::FigurePatch::default().to_json();
        PATCH.with(|b| *b.borrow_mut() = none.into_bytes());
    }
}

/// The details of page `page` of the last scene built (HTML, what the page shows beside the
/// figure), at [`gs_details_ptr`]; returns their length, 0 where there is no such page or no
/// scene was built.
#[no_mangle]
pub extern "C" fn gs_details(page: u32) -> usize {
    install_hook();
    let details = KEPT.with(|k| {
        let k = k.borrow();
        k.as_ref().and_then(|k| k.details(page as usize))
    });
    DETAILS.with(|d| {
        let mut d = d.borrow_mut();
        *d = details.unwrap_or_default().into_bytes();
        d.len()
    })
}

/// Where the details [`gs_details`] gave start.
#[no_mangle]
pub extern "C" fn gs_details_ptr() -> *const u8 {
    DETAILS.with(|d| d.borrow().as_ptr())
}

/// The number of the last figure drawn (0: none yet; 1 follows 2³⁰ − 1).
#[no_mangle]
pub extern "C" fn gs_figure_id() -> u32 {
    FIGURE.with(|f| f.get())
}

/// Where what changed from the page's figure starts (JSON: the root's tag where it changed,
/// the lines `[child, line, text]`, the children `[child, text]` whole).
#[no_mangle]
pub extern "C" fn gs_patch_ptr() -> *const u8 {
    PATCH.with(|o| o.borrow().as_ptr())
}

/// The length of that patch (0: none; the page reads the whole figure).
#[no_mangle]
pub extern "C" fn gs_patch_len() -> usize {
    PATCH.with(|o| o.borrow().len())
}

/// Where the last figure starts (the answer's `svg` field is empty: the figure is apart).
#[no_mangle]
pub extern "C" fn gs_svg_ptr() -> *const u8 {
    SVG.with(|o| o.borrow().0.as_ptr())
}

/// The length of the last figure (0: none drawn yet).
#[no_mangle]
pub extern "C" fn gs_svg_len() -> usize {
    SVG.with(|o| o.borrow().0.len())
}

/// Where the last answer starts.
#[no_mangle]
pub extern "C" fn gs_out_ptr() -> *const u8 {
    OUT.with(|o| o.borrow().as_ptr())
}

/// Where the message of the panic that trapped the last call starts.
#[no_mangle]
pub extern "C" fn gs_panic_ptr() -> *const u8 {
    PANIC.with(|p| p.borrow().as_ptr())
}

/// The length of that message (0: no panic).
#[no_mangle]
pub extern "C" fn gs_panic_len() -> usize {
    PANIC.with(|p| p.borrow().len())
}

/// Keeps a panic's message (one line) where the page can read it after the trap.
fn install_hook() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        std::panic::set_hook(Box::new(|info| {
            let msg = info.to_string().replace('\n', " ");
            PANIC.with(|p| {
                if let Ok(mut p) = p.try_borrow_mut() {
                    *p = msg.into_bytes();
                }
            });
        }))
    });
}

/// `s` as a JSON string.
fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
