//! The `graphostatik` command line: render, check, steps, schema.

use clap::{Parser, Subcommand};
use graphostatik::io::Batch;
use graphostatik::protocol::{Board, BoardConfig, Mode};
use graphostatik::render;
use graphostatik::scene::{AnyProblem, AnyScene, Procedure, TrussScene, REGISTRY};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Digital Graphostatik: replay the ruler-and-compass constructions of the classic textbooks.
#[derive(Parser)]
#[command(name = "graphostatik", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Print only what the command produces (tables, JSON) and errors: no list of files
    /// written, no progress.
    #[arg(short, long, global = true)]
    quiet: bool,
    /// Also print, per scene, its steps, checks and time (on standard error).
    #[arg(short, long, global = true, conflicts_with = "quiet")]
    verbose: bool,
}

/// How much the command says besides its product: 0 quiet, 1 normal, 2 verbose.
static VERBOSITY: std::sync::atomic::AtomicU8 = std::sync::atomic::AtomicU8::new(1);

fn verbosity() -> u8 {
    VERBOSITY.load(std::sync::atomic::Ordering::Relaxed)
}

/// Says a line of chatter (a file written, pages made) unless `--quiet`.
fn chatter(text: &str) -> Result<(), Fail> {
    if verbosity() >= 1 {
        say(text)
    } else {
        Ok(())
    }
}

/// A progress bar on standard error for long batch work: shown only on a terminal and not
/// with `--quiet`; `unit` names what is counted.
fn progress(done: usize, total: usize, unit: &str) {
    use std::io::{IsTerminal, Write};
    // Redrawn when the percentage moves (not 1,200 times for 1,200 drawings).
    let moved = done == total || done * 100 / total.max(1) != (done - 1) * 100 / total.max(1);
    if verbosity() == 0 || !moved || !std::io::stderr().is_terminal() {
        return;
    }
    let bar = "#".repeat(done * 30 / total.max(1));
    let mut e = std::io::stderr().lock();
    let _ = write!(e, "\r[{bar:<30}] {done}/{total} {unit}");
    if done == total {
        let _ = writeln!(e);
    }
    let _ = e.flush();
}

#[derive(Subcommand)]
enum Command {
    /// Render scenes to SVG, one file per scene (a folder renders every *.json in it).
    Render {
        /// Scene files or folders.
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Output folder (created if missing).
        #[arg(long, default_value = "figures")]
        out: PathBuf,
        /// Scenes rendered at once (default: every core). The output is the same for any value.
        #[arg(long, value_parser = clap::value_parser!(u16).range(1..))]
        jobs: Option<u16>,
        /// What to write per scene, one or several (`--format svg,png,pdf,tikz`): SVG with one
        /// Inkscape layer per step, PNG and PDF set in the shipped DejaVu Serif, TikZ with one
        /// scope per step.
        #[arg(long, value_enum, value_delimiter = ',', default_value = "svg")]
        format: Vec<Format>,
        /// Resolution of a PNG, pixels per inch of the sheet.
        #[arg(long, default_value_t = render::export::DEFAULT_DPI)]
        dpi: f32,
        /// The paper to set each figure on: a4, a3, a2, a1 or fit (the figure's own size, the
        /// default unless the scene names a `paper`; this overrides the scene's). On A-series
        /// paper the sheet is reduced at a stated scale (1 : 1 to 1 : 1.4, written under it,
        /// the scales' names restated) so that labels stay at least 2.5 mm high; a figure
        /// too large is split into pages by its rows of parts (name-1.svg, name-2.svg, …, one
        /// PNG a page, one PDF of all pages) or set on larger paper, up to A1, and render
        /// says which. TikZ is always the sheet at its own size.
        #[arg(long, value_parser = paper_arg)]
        paper: Option<graphostatik::protocol::Paper>,
    },
    /// Print the table of every analytic check; exit status 1 if any fails.
    Check {
        /// The scene file.
        scene: PathBuf,
        /// Print JSON instead of a text table.
        #[arg(long)]
        json: bool,
        /// Replay every step in double-double beside f64 and print, per step, the digits f64
        /// lost against the replay and the digits the propagated bound predicted; exit
        /// status 1 if the bound fails anywhere.
        #[arg(long)]
        reference: bool,
        /// List every check: without it, a scene of more than 1,000 checks gets a row per
        /// kind of check (its count and its worst) and every failed check.
        #[arg(long)]
        all: bool,
    },
    /// Sweep the knobs that trade time for accuracy (crank divisions, integration rules, point
    /// loads for a uniform load, f64 against a double-double replay): error against the exact
    /// value and time per run, as a table (and as a log-log plot with --svg).
    Accuracy {
        /// The scene file.
        scene: PathBuf,
        /// Also write the plot of error against time to this SVG file.
        #[arg(long)]
        svg: Option<PathBuf>,
        /// Print JSON instead of a text table.
        #[arg(long)]
        json: bool,
    },
    /// Draw the scene many times by a simulated draftsman's hand (pencil, set square, scale
    /// rule, each a random error of every step) on every core, and print the spread of every
    /// checked value beside the bound the board propagates for that hand.
    Drafting {
        /// The scene file.
        scene: PathBuf,
        /// Standard deviation of a marked point or ruled line (mm): half a pencil line.
        #[arg(long, default_value_t = 0.1)]
        pencil_mm: f64,
        /// Standard deviation of a direction set with the set square or protractor (degrees).
        #[arg(long, default_value_t = 0.1)]
        angle_deg: f64,
        /// Standard deviation of a length set or read on the scale rule (mm).
        #[arg(long, default_value_t = 0.1)]
        read_mm: f64,
        /// Drawings made.
        #[arg(long, default_value_t = 200, value_parser = clap::value_parser!(u32).range(2..=100_000))]
        runs: u32,
        /// Seed of the first drawing (the same seed gives the same table).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Drawings made at once (default: every core). The table is the same for any value.
        #[arg(long, value_parser = clap::value_parser!(u16).range(1..))]
        jobs: Option<u16>,
        /// Print JSON instead of a text table.
        #[arg(long)]
        json: bool,
    },
    /// Write a self-contained walk-through (index.html, the figure inlined once) that shows the
    /// construction one step at a time, with caption, German term, book and checks, and a print view.
    Steps {
        /// The scene file.
        scene: PathBuf,
        /// Output folder (created if missing).
        #[arg(long)]
        out: PathBuf,
        /// Page by single steps (`step`, the default) or by the steps made in one situation,
        /// one joint's polygon or one crank angle (`context`).
        #[arg(long, value_enum, default_value_t = GroupArg::Step)]
        group: GroupArg,
    },
    /// Write a static site of scenes that runs the engine (WebAssembly) in the page: an index
    /// with thumbnails and, per scene, its walk-through in which the student drags the given
    /// points (truss joints, points of application, force directions, the pole, crank pins) and
    /// the scene's `preview.sliders`, the construction and its checks replayed as the pointer
    /// moves. Opens from the file system; no server.
    Site {
        /// Scene files, or folders of scenes (every *.json in them).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Output folder (created if missing).
        #[arg(long)]
        out: PathBuf,
        /// The engine, graphostatik_wasm.wasm (default: where `cargo build -p graphostatik-wasm
        /// --target wasm32-unknown-unknown --profile wasm` puts it beside this program's build).
        #[arg(long)]
        engine: Option<PathBuf>,
    },
    /// Live preview for authors: each scene's walk-through on http://127.0.0.1:PORT/, reloaded
    /// when its file changes; a bad edit shows its error over the last good figure; the
    /// scene's `preview.sliders` move numbers and replay the construction.
    Serve {
        /// A scene file, or a folder whose *.json files are served.
        path: PathBuf,
        /// Port (0: any free one; the address is printed).
        #[arg(long, default_value_t = 8000)]
        port: u16,
        /// Address to listen on. Other than loopback, anyone who can reach this machine can
        /// read the scenes served.
        #[arg(long, default_value = "127.0.0.1")]
        bind: std::net::IpAddr,
        /// The engine, graphostatik_wasm.wasm, as for `site` (without it the pages show the
        /// walk-through alone).
        #[arg(long)]
        engine: Option<PathBuf>,
    },
    /// Print the construction protocol (every step, object and check) as JSON.
    Protocol {
        /// The scene file.
        scene: PathBuf,
    },
    /// Print the table of member forces of a truss scene, per load case and combination.
    Forces {
        /// The truss scene file.
        scene: PathBuf,
        /// markdown, csv or json.
        #[arg(long, default_value = "markdown")]
        format: TableFormat,
    },
    /// Print the JSON Schema of the scene format (with --markdown: the scene reference,
    /// every procedure's fields and the types they use, as docs/scene-reference.md holds it).
    Schema {
        /// The reference as Markdown instead of the schema.
        #[arg(long)]
        markdown: bool,
    },
    /// List the procedures a scene can name, with what each constructs and its outputs.
    Procedures,
    /// Print the shell completion script for bash, zsh, fish, elvish or powershell (e.g.
    /// `graphostatik completions bash > ~/.local/share/bash-completion/completions/graphostatik`).
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// Print the manual page (roff), generated from the command line's definition
    /// (`graphostatik man > graphostatik.1; man ./graphostatik.1`).
    Man,
}

/// Formats of the member-force table.
#[derive(Clone, Copy, clap::ValueEnum)]
enum TableFormat {
    Markdown,
    Csv,
    Json,
}

/// Input errors: exit status 2, one line naming the place.
#[derive(Debug)]
struct Fail(String);

fn scene_files(args: &[PathBuf]) -> Result<Vec<PathBuf>, Fail> {
    let mut files = Vec::new();
    for a in args {
        if a.is_dir() {
            let rd = std::fs::read_dir(a)
                .map_err(|e| Fail(format!("{}: cannot read the folder: {e}", a.display())))?;
            let mut v: Vec<PathBuf> = rd
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "json"))
                .collect();
            v.sort();
            if v.is_empty() {
                return Err(Fail(format!(
                    "{}: no *.json scene in this folder",
                    a.display()
                )));
            }
            files.extend(v);
        } else {
            files.push(a.clone());
        }
    }
    Ok(files)
}

/// Writes to standard output. A reader that has gone away (`… | head`) ends the output
/// quietly, as Unix tools do; any other write error is reported.
fn say(text: &str) -> Result<(), Fail> {
    use std::io::Write;
    let mut o = std::io::stdout().lock();
    match o.write_all(text.as_bytes()).and_then(|_| o.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(Fail(format!("standard output: {e}"))),
    }
}

fn load(path: &Path) -> Result<AnyProblem, Fail> {
    let scene = AnyScene::load(path).map_err(|e| Fail(e.to_string()))?;
    Ok(scene.into_problem())
}

/// A scene read for its checks alone: it may be larger than a figure's, up to half the
/// memory the machine has free.
fn load_for_checks(path: &Path) -> Result<AnyProblem, Fail> {
    let free = graphostatik::io::available_memory();
    let scene = AnyScene::load_for_checks(path, free).map_err(|e| Fail(e.to_string()))?;
    Ok(scene.into_problem())
}

fn construct(path: &Path, p: &AnyProblem) -> Result<Board, Fail> {
    construct_with(path, p, BoardConfig::DRAWING)
}

/// The figure's construction, refused where a part of it would not fit a sheet
/// ([`render::layout::parts_within`]).
fn construct_drawable(path: &Path, p: &AnyProblem) -> Result<Board, Fail> {
    let board = construct(path, p)?;
    let within = render::layout::parts_within(&board, graphostatik::scene::MAX_SHEET_MM);
    within.map_err(|e| match p.error_field(&e) {
        Some(field) => Fail(format!("{}: {field}: {e}", path.display())),
        None => Fail(format!("{}: {e}", path.display())),
    })?;
    Ok(board)
}

fn construct_with(path: &Path, p: &AnyProblem, config: BoardConfig) -> Result<Board, Fail> {
    p.construct(config).map_err(|e| match p.error_field(&e) {
        Some(field) => Fail(format!("{}: {field}: {e}", path.display())),
        None => Fail(format!("{}: {e}", path.display())),
    })
}

fn ensure_dir(dir: &Path, made: &mut MadeDirs) -> Result<(), Fail> {
    // The folders that are not there yet, outermost first: made now, and removed again
    // (while empty) if the write fails.
    let new: Vec<PathBuf> = (dir.ancestors())
        .take_while(|d| !d.as_os_str().is_empty() && std::fs::symlink_metadata(d).is_err())
        .map(Path::to_path_buf)
        .collect();
    let made_all = std::fs::create_dir_all(dir);
    made.0.extend(new.into_iter().rev().filter(|d| d.is_dir()));
    made_all.map_err(|e| {
        made.undo();
        Fail(format!(
            "{}: cannot create the output folder: {e}",
            dir.display()
        ))
    })
}

/// The folders a command made for its output, innermost last.
#[derive(Default)]
struct MadeDirs(Vec<PathBuf>);

impl MadeDirs {
    /// Removes the folders made, innermost first, where they are still empty.
    fn undo(&mut self) {
        for d in self.0.drain(..).rev() {
            let _ = std::fs::remove_dir(d);
        }
    }
}

/// Writes a batch all or nothing: where it fails, the folders made for it go too.
fn commit(batch: Batch, mut made: MadeDirs) -> Result<(), Fail> {
    batch.commit().map_err(|e| {
        made.undo();
        Fail(e.to_string())
    })
}

fn run(cli: Cli) -> Result<ExitCode, Fail> {
    match cli.command {
        Command::Render {
            scenes,
            out,
            jobs,
            format,
            dpi,
            paper,
        } => render_cmd(&scenes, &out, jobs, &Exports::new(format, dpi, paper)?),
        Command::Check {
            scene,
            json,
            reference,
            all,
        } => check_cmd(&scene, json, reference, all),
        Command::Steps { scene, out, group } => steps_cmd(&scene, &out, group),
        Command::Site {
            scenes,
            out,
            engine,
        } => site_cmd(&scenes, &out, engine),
        Command::Serve {
            path,
            port,
            bind,
            engine,
        } => serve_cmd(&path, port, bind, engine),
        Command::Accuracy { scene, svg, json } => accuracy_cmd(&scene, svg.as_deref(), json),
        Command::Drafting {
            scene,
            pencil_mm,
            angle_deg,
            read_mm,
            runs,
            seed,
            jobs,
            json,
        } => {
            let options = drafting_options([pencil_mm, angle_deg, read_mm], runs, seed, jobs)?;
            drafting_cmd(&scene, options, json)
        }
        Command::Protocol { scene } => {
            let p = load(&scene)?;
            let board = construct(&scene, &p)?;
            say(&(board.to_json() + "\n"))?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Forces { scene, format } => forces_cmd(&scene, format),
        Command::Procedures => procedures_cmd(),
        Command::Completions { shell } => completions_cmd(shell),
        Command::Man => man_cmd(),
        Command::Schema { markdown } => {
            let text = if markdown {
                graphostatik::scene::reference_markdown()
            } else {
                graphostatik::scene::schema_json() + "\n"
            };
            say(&text)?;
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// `completions SHELL`: the completion script, from the command line's own definition.
fn completions_cmd(shell: clap_complete::Shell) -> Result<ExitCode, Fail> {
    use clap::CommandFactory;
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "graphostatik", &mut out);
    say(&String::from_utf8_lossy(&out))?;
    Ok(ExitCode::SUCCESS)
}

/// `man`: the manual page (roff), from the same definition.
fn man_cmd() -> Result<ExitCode, Fail> {
    use clap::CommandFactory;
    let mut out = Vec::new();
    clap_mangen::Man::new(Cli::command())
        .render(&mut out)
        .map_err(|e| Fail(format!("the manual page: {e}")))?;
    say(&String::from_utf8_lossy(&out))?;
    Ok(ExitCode::SUCCESS)
}

/// A paper named on the command line (`--paper a4`).
fn paper_arg(name: &str) -> Result<graphostatik::protocol::Paper, String> {
    graphostatik::protocol::Paper::parse(name).ok_or_else(|| {
        format!(
            "unknown paper `{}`: give one of {}",
            graphostatik::fmt::clip(name, 20),
            graphostatik::protocol::Paper::NAMES.join(", ")
        )
    })
}

/// A file format `render` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, clap::ValueEnum)]
enum Format {
    /// SVG, one Inkscape layer per construction step.
    Svg,
    /// PNG at `--dpi` (recorded in the file), text in the shipped DejaVu Serif.
    Png,
    /// PDF, one page the size of the sheet (true scale) or of the paper (a page per page of
    /// a figure split by `--paper`), text as the font's outlines.
    Pdf,
    /// A TikZ picture for LaTeX, one scope per step.
    Tikz,
}

impl Format {
    fn extension(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Png => "png",
            Format::Pdf => "pdf",
            Format::Tikz => "tikz",
        }
    }
}

/// The formats asked for, each once, in a fixed order, and the PNG resolution.
struct Exports {
    formats: Vec<Format>,
    dpi: f32,
    /// The paper asked for on the command line, over the scene's own.
    paper: Option<graphostatik::protocol::Paper>,
}

impl Exports {
    fn new(
        mut formats: Vec<Format>,
        dpi: f32,
        paper: Option<graphostatik::protocol::Paper>,
    ) -> Result<Exports, Fail> {
        formats.sort();
        formats.dedup();
        if formats.contains(&Format::Png) {
            render::export::check_dpi(dpi).map_err(|e| Fail(format!("--dpi: {e}")))?;
        }
        Ok(Exports {
            formats,
            dpi,
            paper,
        })
    }

    /// One constructed scene drawn: its SVG and TikZ (which need the board) and what is to be
    /// said of its lettering once the files are written (the labels the crowd rule left out).
    /// PNG and PDF are made from the SVG afterwards, each a job of its own.
    fn draw(&self, f: &Path, p: &AnyProblem, board: &Board) -> Result<Drawn, Fail> {
        let meta = p.figure_meta();
        let paper = self.paper.or(p.paper()).unwrap_or_default();
        let set = render::paper::on_paper(&meta, board, paper);
        let lettering = set.lettering;
        // What the crowd rule did, said unless `--quiet` (a failed check is said always).
        let mut said = Vec::new();
        said.extend(set.said);
        if lettering.left_out > 0 {
            said.push(format!(
                "{} of {} labels left out, no room for them on the sheet",
                lettering.left_out, lettering.labels
            ));
        }
        if lettering.withheld > 0 {
            said.push(format!(
                "{} names of lines and forces withheld from plans without room for all",
                lettering.withheld
            ));
        }
        let labels = (verbosity() >= 1 && !said.is_empty())
            .then(|| format!("{}: {}", f.display(), said.join("; ")));
        let note = match (labels, failed_checks(f, board)) {
            (Some(a), Some(b)) => Some(format!("{a}\n{b}")),
            (a, b) => a.or(b),
        };
        let tikz = self.formats.contains(&Format::Tikz).then(|| {
            render::export::tikz(&meta, board)
                .map(String::into_bytes)
                .map_err(|e| Fail(format!("{}: {e}", f.display())))
        });
        Ok(Drawn {
            svgs: set.pages.into_iter().map(|p| p.svg).collect(),
            tikz,
            note,
            objects: board.object_count(),
        })
    }

    /// The raster and page formats, made from a drawn figure's pages: a PNG per page, one
    /// PDF of every page.
    fn export(&self, f: &Path, fmt: Format, svgs: &[String]) -> Result<Vec<Vec<u8>>, Fail> {
        let failed = |e: render::export::ExportError| Fail(format!("{}: {e}", f.display()));
        match fmt {
            Format::Png => (svgs.iter())
                .map(|svg| render::export::png(svg, self.dpi).map_err(failed))
                .collect(),
            Format::Pdf => {
                let pages: Vec<&str> = svgs.iter().map(String::as_str).collect();
                Ok(vec![render::export::pdf_pages(&pages).map_err(failed)?])
            }
            Format::Svg | Format::Tikz => unreachable!("drawn with the board"),
        }
    }
}

/// `render`: every scene loaded and constructed before the first file is written.
fn render_cmd(
    scenes: &[PathBuf],
    out: &Path,
    jobs: Option<u16>,
    exports: &Exports,
) -> Result<ExitCode, Fail> {
    let files = scene_files(scenes)?;
    let mut seen: std::collections::BTreeMap<PathBuf, &Path> = Default::default();
    for f in &files {
        let stem = f.file_stem().map(|s| s.to_string_lossy().into_owned());
        let target = out.join(format!("{}.svg", stem.unwrap_or_default()));
        // Two scenes that would write one figure: refused before anything is written.
        if let Some(first) = seen.insert(target.clone(), f) {
            return Err(Fail(format!(
                "{}: would write {} as {} does too: rename one of them",
                f.display(),
                target.display(),
                first.display()
            )));
        }
    }
    let mut batch = Batch::default();
    let mut notes = Vec::new();
    for (f, written) in files.iter().zip(render_all(&files, jobs, exports)) {
        let stem = f.file_stem().map(|s| s.to_string_lossy().into_owned());
        let written = written?;
        notes.extend(written.note);
        for (tail, bytes) in written.files {
            let target = out.join(format!("{}{tail}", stem.as_deref().unwrap_or_default()));
            // A page of a figure split into pages (x-1.svg) that another scene writes too.
            if let Some(first) = seen.insert(target.clone(), f).filter(|&g| g != f.as_path()) {
                return Err(Fail(format!(
                    "{}: would write {} as {} does too: rename one of them",
                    f.display(),
                    target.display(),
                    first.display()
                )));
            }
            batch.add_bytes(target, bytes);
        }
    }
    let mut made = MadeDirs::default();
    ensure_dir(out, &mut made)?;
    let paths: Vec<PathBuf> = batch.paths().map(Path::to_path_buf).collect();
    commit(batch, made)?;
    for path in paths {
        // A name's control characters escaped: it cannot move the terminal's cursor.
        chatter(&format!(
            "{}\n",
            graphostatik::fmt::clip(&path.display().to_string(), usize::MAX)
        ))?;
    }
    for note in notes {
        eprintln!("{note}");
    }
    Ok(ExitCode::SUCCESS)
}

/// The files of one scene (its format and bytes, in the order of the formats) and a note for
/// stderr once they are written.
struct Written {
    /// Each file's name after the scene's (`.svg`, `-2.png` for a figure's second page).
    files: Vec<(String, Vec<u8>)>,
    note: Option<String>,
}

/// A PNG per page or one PDF of every page, or why not.
type Made = Result<Vec<Vec<u8>>, Fail>;

/// A scene constructed and drawn: what needs its board.
struct Drawn {
    /// The figure's SVG, or its pages' where it is set on paper and split.
    svgs: Vec<String>,
    tikz: Option<Result<Vec<u8>, Fail>>,
    note: Option<String>,
    /// The board's objects: what a PNG or PDF of it costs (some 76 µs each).
    objects: usize,
}

/// Renders each scene in every format asked for on every core the machine offers, in two
/// rounds of jobs handed out dearest first ([`graphostatik::jobs::dearest_first`]): each
/// scene read, constructed and drawn (the dearest guessed by the scene file's size), then
/// every PNG and PDF on its own (their cost, by far the largest, follows the drawn objects).
/// The results come back in the order of `files`, so the output and the first error reported
/// are those of a serial run.
fn render_all(
    files: &[PathBuf],
    jobs: Option<u16>,
    exports: &Exports,
) -> Vec<Result<Written, Fail>> {
    let workers = jobs.map(usize::from).unwrap_or_else(cores);
    let done = std::sync::atomic::AtomicUsize::new(0);
    let size = |f: &PathBuf| std::fs::metadata(f).map_or(0, |m| m.len());
    // Each worker thread prepares its own heap once, as `main` prepared the first one's.
    let prepare = heap::prepare_thread;
    let drawn = graphostatik::jobs::dearest_first_on(files, size, workers, prepare, |f| {
        let start = std::time::Instant::now();
        let p = load(f)?;
        let board = construct_drawable(f, &p)?;
        let drawn = exports.draw(f, &p, &board)?;
        if verbosity() >= 2 {
            eprintln!(
                "{}: {} steps, {} checks, {:.1} ms",
                f.display(),
                board.steps().len(),
                board.check_count(),
                start.elapsed().as_secs_f64() * 1e3
            );
        }
        let k = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        progress(k, files.len(), "scenes");
        Ok(drawn)
    });
    // Past the first scene that failed nothing is written: its exports are not made.
    let upto = drawn.iter().position(Result::is_err).unwrap_or(drawn.len());
    let raster: Vec<(usize, Format)> = exports
        .formats
        .iter()
        .filter(|f| matches!(f, Format::Png | Format::Pdf))
        .flat_map(|&fmt| (0..upto).map(move |i| (i, fmt)))
        .collect();
    let objects = |&(i, _): &(usize, Format)| drawn[i].as_ref().map_or(0, |d| d.objects as u64);
    let made =
        graphostatik::jobs::dearest_first_on(&raster, objects, workers, prepare, |&(i, fmt)| {
            let d = drawn[i].as_ref().expect("exports only of drawn scenes");
            exports.export(&files[i], fmt, &d.svgs)
        });
    let mut made: std::collections::BTreeMap<(usize, Format), Made> =
        raster.into_iter().zip(made).collect();
    let written = drawn.into_iter().enumerate().map(|(i, d)| {
        let mut d = d?;
        if i > upto {
            return Err(Fail(format!("{}: not rendered", files[i].display())));
        }
        let mut out = Vec::new();
        for &fmt in &exports.formats {
            let files = match fmt {
                Format::Svg => (d.svgs.iter_mut())
                    .map(|s| std::mem::take(s).into_bytes())
                    .collect(),
                Format::Tikz => vec![d.tikz.take().expect("drawn when asked for")?],
                _ => made
                    .remove(&(i, fmt))
                    .expect("made for every drawn scene")?,
            };
            let paged = files.len() > 1;
            for (k, bytes) in files.into_iter().enumerate() {
                let page = if paged {
                    format!("-{}", k + 1)
                } else {
                    String::new()
                };
                out.push((format!("{page}.{}", fmt.extension()), bytes));
            }
        }
        Ok(Written {
            files: out,
            note: d.note,
        })
    });
    written.collect()
}

/// What `render` and `forces` say on standard error when a check of the construction they
/// drew or read failed (a glancing cut, a value off its closed form): they still write
/// their output, and `check` shows the failures.
fn failed_checks(f: &Path, board: &graphostatik::protocol::Board) -> Option<String> {
    let (n, failed) = (board.check_count(), board.failed_count());
    (failed > 0).then(|| {
        format!(
            "{}: {failed} of {n} checks fail (graphostatik check lists them)",
            f.display()
        )
    })
}

/// `check`: the table of every check, exit status 1 if any fails; with `reference`, every
/// step replayed in double-double beside f64, exit status 1 if the bound fails anywhere.
fn check_cmd(scene: &Path, json: bool, reference: bool, all: bool) -> Result<ExitCode, Fail> {
    let start = std::time::Instant::now();
    // The table needs the checks, not the drawing (a reference replay needs both). The
    // scene is read for the same: what it may ask for follows what is kept.
    let (board, book, any) = if reference {
        let any = AnyScene::load(scene).map_err(|e| Fail(e.to_string()))?;
        let config = BoardConfig::DRAWING.with_reference();
        (
            construct_with(scene, any.problem(), config)?,
            Vec::new(),
            any,
        )
    } else {
        let free = graphostatik::io::available_memory();
        let any = AnyScene::load_for_checks(scene, free).map_err(|e| Fail(e.to_string()))?;
        // Book values are matched against every check: they are all kept then.
        let config = BoardConfig {
            mode: Mode::Checks {
                every: all || !any.book().is_empty(),
            },
            ..BoardConfig::DRAWING
        };
        let board = construct_with(scene, any.problem(), config)?;
        let book = render::book_rows(&board, any.book());
        (board, book, any)
    };
    let text = match (reference, json, book.is_empty()) {
        (false, false, _) => render::check_table_text(&board) + &render::book_table_text(&book),
        (false, true, true) => render::check_table_json(&board) + "\n",
        (false, true, false) => format!(
            "{{\"checks\": {},\n\"book\": {}}}\n",
            render::check_table_json(&board),
            serde_json::to_string_pretty(&book).expect("rows are plain data")
        ),
        (true, false, _) => render::reference_table_text(&board),
        (true, true, _) => render::reference_table_json(&board) + "\n",
    };
    if verbosity() >= 2 {
        eprintln!(
            "{}: {} steps, {} checks, {:.3} ms (read, construction, checks, table)",
            scene.display(),
            board.step_count(),
            board.check_count(),
            start.elapsed().as_secs_f64() * 1e3
        );
    }
    say(&text)?;
    let failed = if reference {
        render::reference_rows(&board).iter().any(|r| !r.within)
    } else {
        !board.all_passed() || book.iter().any(|r| !r.passed())
    };
    // The process ends with the command: the scene (its truss and LU) and the board are
    // left for the system to take back with the rest of the heap instead of being freed
    // object by object (the board of a 10,000-joint girder took 6 M instructions to free).
    std::mem::forget((board, any));
    Ok(if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// `accuracy`: the knobs swept, with a progress line on a terminal (none otherwise).
fn accuracy_cmd(scene: &Path, svg: Option<&Path>, json: bool) -> Result<ExitCode, Fail> {
    let p = load(scene)?;
    // The plot's file is tried before the sweep, which may run for minutes.
    if let Some(path) = svg {
        Batch::check_targets(&[path]).map_err(|e| Fail(format!("--svg {e}")))?;
    }
    let mut progress = |done: usize, total: usize| progress(done, total, "settings");
    let sweeps =
        graphostatik::scene::sweeps(&p, &mut progress).map_err(|e| match p.error_field(&e) {
            Some(field) => Fail(format!("{}: {field}: {e}", scene.display())),
            None => Fail(format!("{}: {e}", scene.display())),
        })?;
    if let Some(path) = svg {
        let title = format!("What accuracy costs: {}", p.figure_meta().title);
        let mut batch = Batch::default();
        batch.add(
            path.to_path_buf(),
            render::accuracy_plot_svg(&title, &sweeps),
        );
        commit(batch, MadeDirs::default())?;
    }
    say_report(json, sweeps.as_slice(), render::accuracy_table_text)?;
    Ok(ExitCode::SUCCESS)
}

/// A report as pretty JSON (`json`) or as the text table `text` makes of it.
fn say_report<T: serde::Serialize + ?Sized>(
    json: bool,
    value: &T,
    text: impl FnOnce(&T) -> String,
) -> Result<(), Fail> {
    if json {
        let s = serde_json::to_string_pretty(value).expect("reports are plain data");
        say(&(s + "\n"))
    } else {
        say(&text(value))
    }
}

/// `drafting`: the scene drawn by a simulated hand, many times.
/// The draftsman's hand from `--pencil-mm`, `--angle-deg` and `--read-mm`, each checked.
fn drafting_options(
    [pencil_mm, angle_deg, read_mm]: [f64; 3],
    runs: u32,
    seed: u64,
    jobs: Option<u16>,
) -> Result<graphostatik::scene::DraftingOptions, Fail> {
    let hand = [
        ("--pencil-mm", pencil_mm),
        ("--angle-deg", angle_deg),
        ("--read-mm", read_mm),
    ];
    if let Some((name, v)) = hand
        .iter()
        .find(|(_, v)| !(v.is_finite() && *v >= 0.0 && *v <= 100.0))
    {
        return Err(Fail(format!(
            "{name}: must be a number from 0 to 100, got {v}"
        )));
    }
    Ok(graphostatik::scene::DraftingOptions {
        hand: graphostatik::protocol::ErrorModel::drafting(
            pencil_mm,
            angle_deg.to_radians(),
            read_mm,
        ),
        runs: runs as usize,
        seed,
        jobs: jobs.map_or_else(cores, usize::from),
    })
}

fn drafting_cmd(
    scene: &Path,
    options: graphostatik::scene::DraftingOptions,
    json: bool,
) -> Result<ExitCode, Fail> {
    let p = load(scene)?;
    let bar = |done: usize, total: usize| progress(done, total, "drawings");
    let report =
        graphostatik::scene::drafting_with_progress(&p, options, &bar).map_err(|e| {
            match p.error_field(&e) {
                Some(field) => Fail(format!("{}: {field}: {e}", scene.display())),
                None => Fail(format!("{}: {e}", scene.display())),
            }
        })?;
    say_report(json, &report, render::drafting_table_text)?;
    Ok(ExitCode::SUCCESS)
}

/// `serve`: the live preview, until the process is stopped.
fn serve_cmd(
    path: &Path,
    port: u16,
    bind: std::net::IpAddr,
    engine: Option<PathBuf>,
) -> Result<ExitCode, Fail> {
    if !path.exists() {
        return Err(Fail(format!("{}: no such scene or folder", path.display())));
    }
    // The engine named must be there; the one beside this build is taken if it is.
    let engine_js = match engine {
        Some(f) => Some(read_engine(&f)?),
        None => default_engine()
            .filter(|f| f.is_file())
            .map(|f| read_engine(&f))
            .transpose()?,
    };
    if engine_js.is_none() {
        eprintln!(
            "note: no engine, so the pages cannot be dragged: {}",
            graphostatik::site::BUILD_ENGINE
        );
    }
    let listener = std::net::TcpListener::bind((bind, port))
        .map_err(|e| Fail(format!("--port {port}: cannot listen on {bind}: {e}")))?;
    let addr = listener
        .local_addr()
        .map_err(|e| Fail(format!("--port {port}: {e}")))?;
    let site = graphostatik::serve::Site::new(path, bind.is_loopback(), addr.port(), engine_js)
        .map_err(|e| Fail(format!("{}: {e}", path.display())))?;
    if !bind.is_loopback() {
        eprintln!(
            "warning: listening on {bind}: anyone who reaches this machine can read the scenes"
        );
    }
    say(&format!(
        "serving {} on http://{addr}/ (Ctrl-C stops)\n",
        path.display()
    ))?;
    graphostatik::serve::run(listener, site);
    Ok(ExitCode::SUCCESS)
}

/// How `steps` pages the construction.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
enum GroupArg {
    /// One construction step per page.
    Step,
    /// The steps made in one situation (a joint, a crank angle) share a page.
    Context,
}

/// `steps`: the self-contained page that walks through the construction one step at a time.
fn steps_cmd(scene: &Path, out: &Path, group: GroupArg) -> Result<ExitCode, Fail> {
    let p = load(scene)?;
    let board = construct_drawable(scene, &p)?;
    let opts = render::WalkOptions {
        grouping: match group {
            GroupArg::Step => render::Grouping::Step,
            GroupArg::Context => render::Grouping::Context,
        },
        ..Default::default()
    };
    let html = render::walkthrough_html(&p.figure_meta(), &board, &opts);
    let mut made = MadeDirs::default();
    ensure_dir(out, &mut made)?;
    let mut batch = Batch::default();
    batch.add(out.join("index.html"), html);
    commit(batch, made)?;
    chatter(&format!(
        "{} steps in {}\n",
        board.steps().len(),
        out.join("index.html").display()
    ))?;
    Ok(ExitCode::SUCCESS)
}

/// `site`: the scenes' pages with the engine, written all or nothing.
fn site_cmd(scenes: &[PathBuf], out: &Path, engine: Option<PathBuf>) -> Result<ExitCode, Fail> {
    let wasm_path = engine.or_else(default_engine).ok_or_else(|| {
        Fail("site: no engine: give --engine FILE (graphostatik_wasm.wasm)".into())
    })?;
    let wasm = read_wasm(&wasm_path)?;
    let mut list = Vec::new();
    for f in scene_files(scenes)? {
        let text = graphostatik::io::read_text(&f, graphostatik::io::MAX_SCENE_BYTES)
            .map_err(|e| Fail(format!("{}: {e}", f.display())))?;
        let name = f
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let origin = f.display().to_string();
        list.push(graphostatik::site::SiteScene { name, origin, text });
    }
    let pages = graphostatik::site::site(&list, &wasm).map_err(|e| match e {
        graphostatik::site::SiteError::Engine(why) => {
            Fail(format!("{}: {why}", wasm_path.display()))
        }
        graphostatik::site::SiteError::Scene(line) => Fail(line),
    })?;
    let mut made = MadeDirs::default();
    ensure_dir(out, &mut made)?;
    ensure_dir(&out.join("thumbs"), &mut made)?;
    let mut batch = Batch::default();
    for p in pages {
        batch.add(out.join(&p.name), p.contents);
    }
    let bytes = batch.bytes();
    commit(batch, made)?;
    chatter(&format!(
        "{} scenes in {} ({:.1} MB, open index.html)\n",
        list.len(),
        out.display(),
        bytes as f64 / 1e6
    ))?;
    Ok(ExitCode::SUCCESS)
}

/// The engine's bytes, or why not, with how to build it.
fn read_wasm(path: &Path) -> Result<Vec<u8>, Fail> {
    std::fs::read(path).map_err(|e| {
        Fail(format!(
            "{}: the engine cannot be read ({e}); build it with `rustup target add \
             wasm32-unknown-unknown && {}`, or name it with --engine",
            path.display(),
            graphostatik::site::BUILD_ENGINE
        ))
    })
}

/// `engine.js` of the engine at `path`.
fn read_engine(path: &Path) -> Result<String, Fail> {
    graphostatik::site::engine_js(&read_wasm(path)?)
        .map_err(|e| Fail(format!("{}: {e}", path.display())))
}

/// Where `cargo build -p graphostatik-wasm --target wasm32-unknown-unknown --profile wasm`
/// puts the engine, beside the build of this program (`target/<profile>/graphostatik`).
fn default_engine() -> Option<PathBuf> {
    let exe = std::env::current_exe().ok()?;
    let target = exe.parent()?.parent()?;
    Some(target.join("wasm32-unknown-unknown/wasm/graphostatik_wasm.wasm"))
}

/// `forces`: the member forces of a truss scene, per case, combination and envelope.
fn forces_cmd(scene: &Path, format: TableFormat) -> Result<ExitCode, Fail> {
    // The table of forces needs the checks, not the drawing.
    let p = load_for_checks(scene)?;
    let Some(t) = p.get::<TrussScene>() else {
        return Err(Fail(format!(
            "{}: `forces` needs a truss scene (\"procedure\": \"truss\")",
            scene.display()
        )));
    };
    let (board, results) = TrussScene::construct(t, BoardConfig::CHECKS)
        .map_err(|e| Fail(format!("{}: {e}", scene.display())))?;
    if let Some(note) = failed_checks(scene, &board) {
        eprintln!("{note}");
    }
    use graphostatik::render::forces;
    let text = match format {
        TableFormat::Markdown if results.len() > 1 => format!(
            "{}\n{}",
            forces::markdown(&results, &t.combinations),
            forces::envelope_markdown(&results, t.envelope.as_ref())
        ),
        TableFormat::Markdown => forces::markdown(&results, &t.combinations),
        TableFormat::Csv => forces::csv(&results, &t.combinations),
        TableFormat::Json => forces::json(&results, &t.combinations, t.envelope.as_ref()) + "\n",
    };
    say(&text)?;
    // As `check`: what was built is left for the system to take back when the process ends.
    std::mem::forget((board, results, p));
    Ok(ExitCode::SUCCESS)
}

/// `procedures`: every procedure a scene can name, with what it constructs and its outputs.
fn procedures_cmd() -> Result<ExitCode, Fail> {
    let mut text = String::new();
    for e in REGISTRY {
        text += &format!("{:<14} {}\n", e.name, e.about);
        if !e.outputs.is_empty() {
            text += &format!("{:<14} outputs: {}\n", "", e.outputs.join(", "));
        }
    }
    say(&text)?;
    Ok(ExitCode::SUCCESS)
}

/// The cores this machine offers (1 if it cannot say).
fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, usize::from)
}

/// The command line read, or its error as one line (exit 2): clap's help and version as
/// clap prints them.
fn parse_cli() -> Result<Cli, ExitCode> {
    use clap::error::ErrorKind;
    match Cli::try_parse() {
        Ok(cli) => Ok(cli),
        Err(e) if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) => {
            let _ = e.print();
            Err(ExitCode::SUCCESS)
        }
        Err(e) if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print();
            Err(ExitCode::from(2))
        }
        Err(e) => {
            eprintln!(
                "error: {}",
                graphostatik::fmt::error_line(&one_line(&e.to_string()))
            );
            Err(ExitCode::from(2))
        }
    }
}

/// clap's error text on one line: its message and tips, without the usage block (which
/// `--help` gives), with what to ask for more.
fn one_line(text: &str) -> String {
    let mut parts: Vec<&str> = Vec::new();
    let mut usage = "";
    for line in text.lines().map(str::trim) {
        if let Some(u) = line.strip_prefix("Usage: ") {
            usage = u;
            continue;
        }
        if line.is_empty() || line.starts_with("For more information") {
            continue;
        }
        parts.push(line.strip_prefix("error: ").unwrap_or(line));
    }
    let mut out = parts.join("; ");
    // The command asked about: the usage's first words before an argument, or the
    // subcommand typed.
    let mut command: Vec<String> = (usage.split_whitespace())
        .take_while(|w| !w.starts_with(['<', '[', '-']))
        .map(str::to_string)
        .collect();
    if command.is_empty() {
        command.push("graphostatik".into());
        let typed = std::env::args().nth(1).filter(|a| !a.starts_with('-'));
        let known = |t: &String| {
            <Cli as clap::CommandFactory>::command()
                .find_subcommand(t)
                .is_some()
        };
        if let Some(sub) = typed.filter(known) {
            command.push(sub);
        }
    }
    let command = command.join(" ");
    out.push_str(&format!(" (`{command} --help` lists them)"));
    out
}

fn main() -> ExitCode {
    let cli = match parse_cli() {
        Ok(cli) => cli,
        Err(code) => return code,
    };
    if !matches!(cli.command, Command::Serve { .. }) {
        heap::prepare();
        clean_up_when_stopped();
    }
    let level = if cli.quiet {
        0
    } else if cli.verbose {
        2
    } else {
        1
    };
    VERBOSITY.store(level, std::sync::atomic::Ordering::Relaxed);
    match run(cli) {
        Ok(code) => code,
        Err(Fail(msg)) => {
            eprintln!("error: {}", graphostatik::fmt::error_line(&msg));
            ExitCode::from(2)
        }
    }
}

/// On Ctrl-C (SIGINT) or SIGTERM, the temporaries the command has written are removed
/// (after a batch's renames, if one is renaming, have ended or rolled back) before it exits
/// with 128 + the signal's number, as a shell reports a stopped command.
fn clean_up_when_stopped() {
    use signal_hook::consts::{SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM]) else {
        return;
    };
    let _ = std::thread::Builder::new()
        .name("signals".into())
        .stack_size(64 * 1024)
        .spawn(move || {
            if let Some(sig) = signals.forever().next() {
                graphostatik::io::abandon();
                std::process::exit(128 + sig);
            }
        });
}

/// The heap of a command that runs once and ends (every command but `serve`).
///
/// A `check` of a 10,000-joint girder touches some 26 MB of fresh heap. With glibc's defaults
/// that is 7,900 page faults of 4 KiB, and on a virtual machine a fault costs microseconds:
/// a fifth of the command's wall time went to the kernel. So, once at the start: the heap
/// grows by one stretch of [`REGION`] (address space only; a page is backed when first
/// touched), the kernel is asked to back it with huge pages where it can
/// (`MADV_HUGEPAGE`, transparent huge pages in their `madvise` mode), and nothing is handed
/// back to the system before the command ends. Past the stretch the heap grows as before.
/// Where the heap cannot grow so (a tight `RLIMIT_DATA`), nothing changes. The bytes a
/// command writes do not depend on any of this; `docs/performance.md` has the numbers.
mod heap {
    /// The stretch the heap grows by at the start: the peak of a 100,000-joint check fits.
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    const REGION: usize = 256 << 20;

    /// Prepares the heap (Linux with glibc; elsewhere a no-op).
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    pub fn prepare() {
        const HUGE_PAGE: usize = 2 << 20;
        const DEFAULT_TOP_PAD: i32 = 128 << 10;
        // SAFETY: mallopt, sbrk(0), malloc, free and madvise are called as glibc documents
        // them: sbrk(0) only reads the break, the block is freed once, and madvise is given
        // a range inside the heap just grown, aligned to the huge page.
        unsafe {
            // Blocks up to 32 MiB (glibc's largest threshold) from the heap, not mmap: the
            // heap is what is prepared. Never trimmed: the command ends soon.
            libc::mallopt(libc::M_MMAP_THRESHOLD, 32 << 20);
            libc::mallopt(libc::M_TRIM_THRESHOLD, i32::MAX);
            libc::mallopt(libc::M_TOP_PAD, REGION as i32);
            let before = libc::sbrk(0) as usize;
            let block = libc::malloc(1 << 20);
            libc::free(std::hint::black_box(block));
            let after = libc::sbrk(0) as usize;
            libc::mallopt(libc::M_TOP_PAD, DEFAULT_TOP_PAD);
            let start = before.next_multiple_of(HUGE_PAGE);
            if before != usize::MAX && after > start {
                libc::madvise(
                    start as *mut libc::c_void,
                    after - start,
                    libc::MADV_HUGEPAGE,
                );
            }
        }
    }

    /// Prepares the heap the calling thread allocates from, where that is a heap of its own
    /// (Linux with glibc; elsewhere a no-op); once per thread, at its start. glibc gives a
    /// thread that is not the first an arena of its own, on heaps of 64 MiB that each start
    /// at a multiple of 64 MiB, made writable a page at a time as they grow (a `mprotect`
    /// each: a thousand for the bundled figures); and a huge page needs its whole 2 MiB
    /// writable. So the heap is grown at once by a block of 30 MiB (below the 32 MiB
    /// [`prepare`] sends to `mmap`), the kernel asked for huge pages over it, and the block
    /// freed, never trimmed.
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    pub fn prepare_thread() {
        const ARENA_HEAP: usize = 64 << 20;
        // SAFETY: the block is allocated and freed once, and madvise only hints at how the
        // pages of a range are backed: on any range it changes no byte of memory.
        unsafe {
            let block = libc::malloc(30 << 20);
            let at = block as usize;
            if !block.is_null() && at > libc::sbrk(0) as usize {
                let base = at & !(ARENA_HEAP - 1);
                libc::madvise(base as *mut libc::c_void, ARENA_HEAP, libc::MADV_HUGEPAGE);
            }
            libc::free(block);
        }
    }

    /// Prepares the heap (Linux with glibc; elsewhere a no-op).
    #[cfg(not(all(target_os = "linux", target_env = "gnu")))]
    pub fn prepare() {}

    /// Prepares a thread's heap (Linux with glibc; elsewhere a no-op).
    #[cfg(not(all(target_os = "linux", target_env = "gnu")))]
    pub fn prepare_thread() {}
}
