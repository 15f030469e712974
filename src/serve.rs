//! The live preview of `graphostatik serve SCENE|DIR`: a small HTTP server on loopback that
//! shows each scene's page as `graphostatik site` writes it (the walk-through, the engine in
//! the page: drag the given points, move the scene's `preview.sliders`), reloads it when the
//! scene file changes, and keeps the last good figure under the error line of an invalid
//! edit. One page serves both: the site's, plus the file watching.
//!
//! It reads only the scene it was given, or the `*.json` files of the folder it was given,
//! looked up by name (a request never names a path), and answers only GET. Bound to
//! 127.0.0.1 unless told otherwise; a request whose `Host` is not this machine's loopback name
//! is refused while bound there (DNS rebinding).

use crate::render::{with_policy, Allow};
use crate::site::{scene_page, PageLinks, SiteScene};
use crate::web::Built;
use std::collections::HashMap;
use std::io::Write;
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

/// How often the page asks whether its scene changed (ms).
pub const POLL_MS: u32 = 500;
/// Longest request head read (bytes): a longer one is answered 431 and closed.
pub const MAX_HEAD: usize = 16 * 1024;
/// Time a client has to send its request head (a slow or idle client is closed after it).
pub const HEAD_DEADLINE: Duration = Duration::from_secs(5);
/// Connections served at once. Beyond them a new connection takes the place of the one that
/// has waited longest without sending its request (an idle client cannot hold the slots a
/// working one needs); where every connection is being answered, it is answered 503 and
/// closed.
pub const MAX_CONNECTIONS: usize = 128;
/// The memory the pages take at once: those being built, by their estimate
/// ([`PAGE_BYTES_PER_STEP`] a step), and those kept or being sent ([`KEPT_BYTES`] of them
/// while idle; one being sent is not let go). A build past it waits up to [`BUILD_WAIT`] for
/// others to finish, then is answered 503 with `Retry-After`.
pub const BUILD_BUDGET_BYTES: usize = 1 << 30;
/// What a page build takes per step of its construction, measured: 16 cylinders at 100
/// divisions, 49,885 steps, a 30 MB page, 213 MB at its peak.
pub const PAGE_BYTES_PER_STEP: usize = 5 * 1024;
/// How long a page build waits for the budget.
pub const BUILD_WAIT: Duration = Duration::from_secs(10);
/// The slowest an answer is read: each piece of [`ANSWER_PIECE`] bytes must be taken within
/// [`ANSWER_GRACE`] and its share at this rate, or the client is dropped (a slow reader
/// cannot hold a slot for longer than its socket's buffers and a piece take).
pub const MIN_READ_BYTES_PER_SEC: usize = 256 * 1024;
/// The time each piece of an answer has besides its share at [`MIN_READ_BYTES_PER_SEC`].
pub const ANSWER_GRACE: Duration = Duration::from_secs(2);
/// The pieces an answer is written in (bytes).
pub const ANSWER_PIECE: usize = 64 * 1024;

/// What the server serves: one scene file, or the `*.json` of one folder.
#[derive(Debug, Clone)]
pub struct Site {
    root: PathBuf,
    single: bool,
    /// Whether the listener is on loopback (then only loopback host names are answered).
    loopback: bool,
    port: u16,
    /// Per scene, its last good construction and its last page built (see [`Kept`]).
    kept: Arc<Mutex<Kept>>,
    /// The memory page builds in flight take.
    budget: Arc<Budget>,
    /// A lock per scene that is being built: a page asked for by many at once is built once,
    /// the others wait for it and take it built.
    building: Arc<Mutex<HashMap<String, Arc<Mutex<()>>>>>,
    /// `engine.js` (the engine inlined), when the engine was found.
    engine: Option<Arc<str>>,
}

/// The memory that page builds in flight may take, by their estimates, and a wait for it.
#[derive(Debug)]
struct Budget {
    used: Mutex<usize>,
    freed: Condvar,
    total: usize,
}

/// A share of the [`Budget`], given back when dropped.
struct Taken<'a> {
    budget: &'a Budget,
    bytes: usize,
}

impl Budget {
    fn new(total: usize) -> Budget {
        Budget {
            used: Mutex::new(0),
            freed: Condvar::new(),
            total,
        }
    }

    /// `bytes` of the budget (at most all of it, less what `held` says is held elsewhere: the
    /// pages kept and being sent), waiting up to `wait` for others to give theirs back;
    /// `None` where they did not.
    fn take(&self, bytes: usize, wait: Duration, held: &dyn Fn() -> usize) -> Option<Taken<'_>> {
        let bytes = bytes.min(self.total);
        let until = Instant::now() + wait;
        let mut used = self.used.lock().unwrap_or_else(|e| e.into_inner());
        while *used + bytes + held() > self.total {
            let left = until.saturating_duration_since(Instant::now());
            if left.is_zero() {
                return None;
            }
            // A page sent to its end frees its bytes without a word: looked at again soon.
            let nap = left.min(Duration::from_millis(100));
            used = (self.freed.wait_timeout(used, nap))
                .unwrap_or_else(|e| e.into_inner())
                .0;
        }
        *used += bytes;
        Some(Taken {
            budget: self,
            bytes,
        })
    }
}

impl Drop for Taken<'_> {
    fn drop(&mut self) {
        let mut used = self.budget.used.lock().unwrap_or_else(|e| e.into_inner());
        *used -= self.bytes;
        self.budget.freed.notify_all();
    }
}

/// The last construction of a scene that succeeded: shown under the error of a bad edit.
#[derive(Debug, Clone)]
struct Good {
    text: String,
    built: Arc<Built>,
}

impl Good {
    /// About the bytes it holds.
    fn bytes(&self) -> usize {
        let b = &self.built;
        self.text.len()
            + b.svg.len()
            + b.items
                .iter()
                .chain(&b.details)
                .map(String::len)
                .sum::<usize>()
            + 256 * (b.steps.len() + b.checks.len())
    }
}

/// What the server keeps of each scene: its last good construction and its last page, by
/// its file's version (asked again unchanged, a page is answered without a build and every
/// client reads the same bytes). At most [`KEPT_BYTES`] in all: past them the scenes asked
/// for longest ago are let go (the scene asked for now is always kept).
#[derive(Debug, Default)]
struct Kept {
    by_name: HashMap<String, KeptScene>,
    asked: u64,
}

#[derive(Debug, Default)]
struct KeptScene {
    good: Option<Good>,
    page: Option<(String, Answer)>,
    asked: u64,
}

impl KeptScene {
    fn bytes(&self) -> usize {
        self.good.as_ref().map_or(0, Good::bytes)
            + self.page.as_ref().map_or(0, |(_, a)| a.body.len())
    }

    /// Whether its page is being sent to a client now (then letting it go frees nothing).
    fn sending(&self) -> bool {
        (self.page.as_ref()).is_some_and(|(_, a)| Arc::strong_count(&a.body) > 1)
    }
}

/// Most bytes the server keeps of built scenes and pages ([`Kept`]).
pub const KEPT_BYTES: usize = 256 << 20;

impl Kept {
    /// The page of `name` built from the file's version `token`, if it is kept.
    fn page(&mut self, name: &str, token: &str) -> Option<Answer> {
        self.asked += 1;
        let k = self.by_name.get_mut(name)?;
        k.asked = self.asked;
        (k.page.as_ref()).and_then(|(v, a)| (v == token).then(|| a.clone()))
    }

    /// Lets go of the scenes asked for longest ago (but `name`, and one whose page is being
    /// sent) while more than [`KEPT_BYTES`] are kept; gives the bytes kept then, those of
    /// pages being sent included.
    fn trim(&mut self, name: Option<&str>) -> usize {
        let mut total: usize = self.by_name.values().map(KeptScene::bytes).sum();
        while total > KEPT_BYTES {
            let Some(oldest) = (self.by_name.iter())
                .filter(|(n, k)| Some(n.as_str()) != name && !k.sending())
                .min_by_key(|(_, k)| k.asked)
                .map(|(n, _)| n.clone())
            else {
                break;
            };
            if let Some(k) = self.by_name.remove(&oldest) {
                total -= k.bytes();
            }
        }
        total
    }

    /// Keeps what a build of `name` gave, and lets go of the scenes asked for longest ago
    /// while more than [`KEPT_BYTES`] are kept (but not one whose page is being sent: its
    /// bytes stay counted until it is).
    fn keep(&mut self, name: &str, good: Option<Good>, page: Option<(String, Answer)>) {
        self.asked += 1;
        let k = self.by_name.entry(name.to_string()).or_default();
        k.asked = self.asked;
        if good.is_some() {
            k.good = good;
        }
        if page.is_some() {
            k.page = page;
        }
        self.trim(Some(name));
    }
}

/// An HTTP answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// Status code.
    pub status: u16,
    /// Content type.
    pub content_type: &'static str,
    /// Body, shared by every client it is written to.
    pub body: Arc<str>,
    /// Seconds after which to ask again (503 of a busy server).
    pub retry_after: Option<u32>,
}

impl Answer {
    fn html(body: String) -> Answer {
        Answer {
            status: 200,
            content_type: "text/html; charset=utf-8",
            body: body.into(),
            retry_after: None,
        }
    }
    fn script(body: Arc<str>) -> Answer {
        Answer {
            status: 200,
            content_type: "text/javascript; charset=utf-8",
            body,
            retry_after: None,
        }
    }
    fn text(status: u16, body: impl Into<String>) -> Answer {
        Answer {
            status,
            content_type: "text/plain; charset=utf-8",
            body: body.into().into(),
            retry_after: None,
        }
    }
    /// A build that found no room in the budget: ask again in a second.
    fn busy() -> Answer {
        Answer {
            retry_after: Some(1),
            ..Answer::text(
                503,
                "busy: other pages are being built; ask again in a second",
            )
        }
    }
}

impl Site {
    /// A site for `path` (a scene file or a folder of scenes) behind a listener on `port`,
    /// with the engine's `engine.js` ([`crate::site::engine_js`]) if there is one.
    pub fn new(
        path: &Path,
        loopback: bool,
        port: u16,
        engine: Option<String>,
    ) -> std::io::Result<Site> {
        let meta = std::fs::metadata(path)?;
        Ok(Site {
            root: path.to_path_buf(),
            single: meta.is_file(),
            loopback,
            port,
            kept: Default::default(),
            budget: Arc::new(Budget::new(BUILD_BUDGET_BYTES)),
            building: Default::default(),
            engine: engine.map(Arc::from),
        })
    }

    /// The scenes by name (file stem), read from the folder now, so that a new file shows.
    fn scenes(&self) -> Vec<(String, PathBuf)> {
        let files: Vec<PathBuf> = if self.single {
            vec![self.root.clone()]
        } else {
            // Only regular files of the folder itself: a link is not followed out of it.
            let mut v: Vec<PathBuf> = std::fs::read_dir(&self.root)
                .map(|d| {
                    d.flatten()
                        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
                        .map(|e| e.path())
                        .filter(|p| p.extension().is_some_and(|x| x == "json"))
                        .collect()
                })
                .unwrap_or_default();
            v.sort();
            v
        };
        files
            .into_iter()
            .filter_map(|p| Some((p.file_stem()?.to_str()?.to_string(), p)))
            .collect()
    }

    fn scene(&self, name: &str) -> Option<PathBuf> {
        self.scenes()
            .into_iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| p)
    }

    /// The answer to `GET target` with this `Host` header.
    pub fn answer(&self, target: &str, host: Option<&str>) -> Answer {
        if self.loopback && !host.is_some_and(|h| self.is_loopback_host(h)) {
            return Answer::text(421, "this preview answers only on its loopback address");
        }
        let path = target.split_once('?').map_or(target, |(p, _)| p);
        if path == "/" {
            return self.index();
        }
        if path == "/page.js" {
            return Answer::script(Arc::from(crate::site::PAGE_JS));
        }
        if path == "/engine.js" {
            return match &self.engine {
                Some(js) => Answer::script(Arc::clone(js)),
                None => Answer::text(404, "no engine"),
            };
        }
        if path == "/favicon.ico" {
            // No icon, and no 404 in the browser's console for it.
            return Answer::text(204, "");
        }
        if let Some(name) = path.strip_prefix("/scene/") {
            let name = percent_decode(name);
            return match self.scene(&name) {
                Some(file) => self.page(&name, &file),
                None => Answer::text(404, "no such scene"),
            };
        }
        if let Some(name) = path.strip_prefix("/version/") {
            let name = percent_decode(name);
            return match self.scene(&name) {
                Some(file) => Answer::text(200, version(&file)),
                None => Answer::text(404, "no such scene"),
            };
        }
        Answer::text(404, "not found")
    }

    /// Whether a request may come from where it says: a browser names another site in
    /// `Origin` (a script's request) or `Sec-Fetch-Site: cross-site` (any request it makes for
    /// a page of another site); the preview's own pages, a typed address and a tool that
    /// sends neither header may ask.
    fn same_origin(
        &self,
        origin: Option<&str>,
        fetch_site: Option<&str>,
        host: Option<&str>,
    ) -> bool {
        if fetch_site.is_some_and(|f| f.eq_ignore_ascii_case("cross-site")) {
            return false;
        }
        let Some(o) = origin.filter(|o| *o != "null") else {
            return true;
        };
        let Some(h) = o
            .to_ascii_lowercase()
            .strip_prefix("http://")
            .map(str::to_string)
        else {
            return false;
        };
        if self.loopback {
            self.is_loopback_host(&h)
        } else {
            host.is_some_and(|host| host.eq_ignore_ascii_case(&h))
        }
    }

    fn is_loopback_host(&self, host: &str) -> bool {
        let port = format!(":{}", self.port);
        let host = host.to_ascii_lowercase();
        ["127.0.0.1", "localhost", "[::1]"]
            .iter()
            .any(|h| host == *h || host.strip_suffix(port.as_str()) == Some(*h))
    }

    fn index(&self) -> Answer {
        let scenes = self.scenes();
        if self.single {
            if let Some((name, file)) = scenes.first() {
                return self.page(name, file);
            }
        }
        let mut items = String::new();
        for (name, _) in &scenes {
            let n = crate::render::html_text(name);
            let href = percent_encode(name);
            items.push_str(&format!("<li><a href=\"/scene/{href}\">{n}</a></li>\n"));
        }
        Answer::html(with_policy(
            format!(
            "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>graphostatik \
             preview</title><style>{INDEX_CSS}</style></head>\n<body>\
             <h1>Scenes in {}</h1>\n<ul>\n{items}</ul>\n</body></html>\n",
            // The folder's own name, not its path on this machine.
            crate::render::html_text(
                &self.root.file_name().map_or_else(|| ".".into(), |n| n.to_string_lossy())
            )
        ),
            &[],
            &[INDEX_CSS],
            Allow::default(),
        ))
    }

    /// A scene's page with the reload script; on a bad edit, the error line over the last
    /// good construction.
    ///
    /// A page asked again while its file is unchanged is the page built before. A build
    /// first estimates what it will take (a construction that keeps nothing counts its
    /// steps) and waits for that share of [`BUILD_BUDGET_BYTES`].
    fn page(&self, name: &str, file: &Path) -> Answer {
        let token = version(file);
        let cached = || {
            let mut kept = self.kept.lock().unwrap_or_else(|e| e.into_inner());
            kept.page(name, &token)
        };
        if let Some(a) = cached() {
            return a;
        }
        // One build of a scene at a time; the others asking for it wait and take it built.
        let lock = {
            let mut b = self.building.lock().unwrap_or_else(|e| e.into_inner());
            Arc::clone(b.entry(name.to_string()).or_default())
        };
        let _one = lock.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(a) = cached() {
            return a;
        }
        let held = || {
            self.kept
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .trim(None)
        };
        // The file read once, for the estimate and the build.
        let origin = file.display().to_string();
        let text = crate::io::read_text(file, crate::io::MAX_SCENE_BYTES)
            .map_err(|e| format!("{origin}: {e}"));
        let cost = text.as_deref().map_or(0, page_cost);
        let Some(_taken) = self.budget.take(cost, BUILD_WAIT, &held) else {
            return Answer::busy();
        };
        let built = text.and_then(|text| build(text, &origin));
        let ok = built.is_ok();
        let (shown, error) = match built {
            Ok(g) => (Some(g), None),
            Err(e) => {
                let kept = self.kept.lock().unwrap_or_else(|e| e.into_inner());
                let good = kept.by_name.get(name).and_then(|k| k.good.clone());
                (good, Some(e))
            }
        };
        let answer = self.page_answer(name, &origin, &token, shown.as_ref(), error);
        if ok {
            let mut kept = self.kept.lock().unwrap_or_else(|e| e.into_inner());
            kept.keep(name, shown, Some((token, answer.clone())));
        }
        answer
    }

    /// The page of scene `name` (read from `origin`, its file's version `token`): the
    /// construction `shown` with the error line of a bad edit over it, or the error alone
    /// where the scene never succeeded.
    fn page_answer(
        &self,
        name: &str,
        origin: &str,
        token: &str,
        shown: Option<&Good>,
        error: Option<String>,
    ) -> Answer {
        let reload = reload_script(name, token);
        match shown {
            Some(g) => Answer::html(scene_page(
                &SiteScene {
                    name: name.to_string(),
                    origin: origin.to_string(),
                    text: g.text.clone(),
                },
                &g.built,
                &PageLinks {
                    index: "/".into(),
                    scripts: "/".into(),
                    engine: self.engine.is_some(),
                    error,
                    inline_scripts: vec![reload],
                    connect: true,
                },
            )),
            None => Answer::html(with_policy(
                format!(
                    "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{t}\
                     </title><style>{ERROR_CSS}</style></head>\n<body><p id=\"wt-error\" \
                     role=\"alert\">{e}</p>\n<script>{reload}</script></body></html>\n",
                    t = crate::render::html_text(name),
                    e = crate::render::html_text(error.as_deref().unwrap_or_default()),
                ),
                &[&reload],
                &[ERROR_CSS],
                Allow {
                    connect: true,
                    ..Allow::default()
                },
            )),
        }
    }
}

/// What building the page of the scene `text` takes, estimated from its steps, counted by a
/// construction that keeps nothing (a figure's limit at most: the build refuses more); a
/// scene that cannot be read costs little (its error page).
fn page_cost(text: &str) -> usize {
    let steps = crate::scene::AnyScene::from_json(text, "")
        .ok()
        .and_then(|s| {
            s.problem()
                .construct(crate::protocol::BoardConfig::SILENT)
                .ok()
        })
        .map_or(0, |b| b.step_count());
    steps.min(crate::scene::MAX_FIGURE_STEPS) * PAGE_BYTES_PER_STEP + 8 * text.len()
}

/// Constructs a scene read from `origin` for its page; the error as one line naming the file
/// and the field.
fn build(text: String, origin: &str) -> Result<Good, String> {
    let built = crate::web::build(&text, origin)?;
    Ok(Good {
        text,
        built: Arc::new(built),
    })
}

/// The index's style sheet.
const INDEX_CSS: &str = "body { font-family: Georgia, serif; }";
/// The style sheet of a scene's page that failed before it ever succeeded.
const ERROR_CSS: &str = "#wt-error { font-family: monospace; color: #8a1d12; }";

/// The file watching: the page asks for the scene's version and reloads when it changes (the
/// step shown is kept in the address). The script's text, to be put inline.
fn reload_script(name: &str, token: &str) -> String {
    // The name is percent-encoded: no `<` can end the script.
    let name = serde_json::to_string(&percent_encode(name)).unwrap_or_default();
    let token = serde_json::to_string(token).unwrap_or_default();
    format!(
        "\n(function () {{\n'use strict';\nvar name = {name}, token = {token};\n\
         setInterval(function () {{\n  fetch('/version/' + name, {{ cache: 'no-store' }})\n\
         .then(function (r) {{ return r.ok ? r.text() : token; }})\n\
         .then(function (t) {{ if (t !== token) window.location.reload(); }})\n\
         .catch(function () {{}});\n}}, {POLL_MS});\n}})();\n"
    )
}

/// A token that changes when the file does (length and modification time).
fn version(file: &Path) -> String {
    match std::fs::metadata(file) {
        Ok(m) => {
            let t = m
                .modified()
                .ok()
                .and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok())
                .map_or(0, |d| d.as_nanos());
            format!("{:x}-{t:x}", m.len())
        }
        Err(_) => "missing".into(),
    }
}

fn percent_decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        match b[i] {
            b'%' if i + 2 < b.len() => match (hex(b[i + 1]), hex(b[i + 2])) {
                (Some(h), Some(l)) => {
                    out.push((h * 16 + l) as u8);
                    i += 3;
                    continue;
                }
                _ => out.push(b'%'),
            },
            b'+' => out.push(b' '),
            c => out.push(c),
        }
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

fn percent_encode(s: &str) -> String {
    s.bytes()
        .map(|c| match c {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' | b'~' => {
                (c as char).to_string()
            }
            _ => format!("%{c:02X}"),
        })
        .collect()
}

/// Serves `site` on `listener` until the process ends: a thread per connection, at most
/// [`MAX_CONNECTIONS`] at once, each with [`HEAD_DEADLINE`] to send a head of at most
/// [`MAX_HEAD`] bytes, one request each, its answer read at [`MIN_READ_BYTES_PER_SEC`] at
/// least. When all are taken, a new connection takes the place of the one that has waited
/// longest without sending its request; where none waits, it is answered 503 and closed.
pub fn run(listener: TcpListener, site: Site) {
    let conns = Arc::new(Mutex::new(Conns::default()));
    for mut stream in listener.incoming().flatten() {
        let Some(id) = admit(&conns, &stream) else {
            refuse(&mut stream, 503, "busy: too many connections");
            continue;
        };
        let (site, held) = (site.clone(), Arc::clone(&conns));
        let spawned = std::thread::Builder::new()
            .stack_size(256 * 1024)
            .spawn(move || {
                let _ = handle(stream, &site, &|| asked(&held, id));
                left(&held, id);
            });
        if spawned.is_err() {
            left(&conns, id);
        }
    }
}

/// The connections open: each its id, a handle to close it by, when it came and whether its
/// request has come yet.
#[derive(Default)]
struct Conns {
    next: u64,
    open: Vec<Conn>,
    /// Connections closed for newer ones whose threads have not ended yet.
    closing: usize,
}

struct Conn {
    id: u64,
    stream: Option<TcpStream>,
    since: Instant,
    waiting: bool,
}

/// A place for `stream` among the connections, its id; where all are taken, the connection
/// that has waited longest without its request is closed for it (its thread ends at its next
/// read). `None` where every connection is being answered.
fn admit(conns: &Mutex<Conns>, stream: &TcpStream) -> Option<u64> {
    let mut c = conns.lock().unwrap_or_else(|e| e.into_inner());
    if c.open.len() >= MAX_CONNECTIONS {
        // The threads of closed connections end at once; more than a round of them
        // pending means they do not, and nothing more is taken.
        if c.closing >= MAX_CONNECTIONS {
            return None;
        }
        let oldest = (c.open.iter().enumerate())
            .filter(|(_, k)| k.waiting)
            .min_by_key(|(_, k)| k.since)
            .map(|(i, _)| i)?;
        let gone = c.open.swap_remove(oldest);
        if let Some(s) = gone.stream {
            let _ = s.shutdown(std::net::Shutdown::Both);
        }
        // Its id is not found when its thread leaves: it counts as closing until then.
        c.closing += 1;
    }
    c.next += 1;
    let id = c.next;
    c.open.push(Conn {
        id,
        stream: stream.try_clone().ok(),
        since: Instant::now(),
        waiting: true,
    });
    Some(id)
}

/// Connection `id` has sent its request: it is no longer closed for a newer one.
fn asked(conns: &Mutex<Conns>, id: u64) {
    let mut c = conns.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(k) = c.open.iter_mut().find(|k| k.id == id) {
        k.waiting = false;
        k.stream = None;
    }
}

/// Connection `id` has ended.
fn left(conns: &Mutex<Conns>, id: u64) {
    let mut c = conns.lock().unwrap_or_else(|e| e.into_inner());
    match c.open.iter().position(|k| k.id == id) {
        Some(i) => {
            c.open.swap_remove(i);
        }
        None => c.closing = c.closing.saturating_sub(1),
    }
}

/// A short answer written without waiting long, then the connection closed.
fn refuse(stream: &mut TcpStream, status: u16, text: &str) {
    let _ = stream.set_write_timeout(Some(Duration::from_millis(200)));
    // One write, not one per formatted piece: the connection is closed right after, with the
    // client's request unread, and a reset may cut off whatever has not left yet.
    let answer = format!(
        "HTTP/1.1 {status} {}\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: {}\r\n\
         Connection: close\r\n\r\n{text}",
        reason(status),
        text.len()
    );
    let _ = stream.write_all(answer.as_bytes());
}

fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        204 => "No Content",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        431 => "Request Header Fields Too Large",
        503 => "Service Unavailable",
        _ => "Misdirected Request",
    }
}

/// The request head, read within [`HEAD_DEADLINE`] and [`MAX_HEAD`] bytes; `Err` with the
/// status to answer otherwise.
fn read_head(stream: &mut TcpStream) -> Result<Vec<String>, u16> {
    use std::io::Read;
    let deadline = std::time::Instant::now() + HEAD_DEADLINE;
    let mut head = Vec::new();
    let mut buf = [0u8; 2048];
    loop {
        let end = head
            .windows(4)
            .position(|w| w == b"\r\n\r\n")
            .map(|i| i + 4)
            .or_else(|| head.windows(2).position(|w| w == b"\n\n").map(|i| i + 2));
        if let Some(end) = end {
            if end > MAX_HEAD {
                return Err(431);
            }
            head.truncate(end);
            break;
        }
        if head.len() > MAX_HEAD {
            return Err(431);
        }
        let left = deadline.saturating_duration_since(std::time::Instant::now());
        if left.is_zero() || stream.set_read_timeout(Some(left)).is_err() {
            return Err(408);
        }
        // No more than one byte past the limit is read: a head is refused at its limit.
        let room = (MAX_HEAD + 1 - head.len()).min(buf.len());
        match stream.read(&mut buf[..room]) {
            Ok(0) => break,
            Ok(n) => head.extend_from_slice(&buf[..n]),
            Err(_) => return Err(408),
        }
    }
    Ok(String::from_utf8_lossy(&head)
        .lines()
        .map(|l| l.trim_end().to_string())
        .take_while(|l| !l.is_empty())
        .collect())
}

/// A header's value, by its name in any case.
fn header<'a>(head: &'a [String], name: &str) -> Option<&'a str> {
    head.iter().skip(1).find_map(|h| {
        let (k, v) = h.split_once(':')?;
        k.trim().eq_ignore_ascii_case(name).then(|| v.trim())
    })
}

fn handle(mut stream: TcpStream, site: &Site, asked: &dyn Fn()) -> std::io::Result<()> {
    let head = match read_head(&mut stream) {
        Ok(h) => {
            asked();
            h
        }
        Err(status) => {
            refuse(
                &mut stream,
                status,
                "the request head must come whole and soon",
            );
            return Ok(());
        }
    };
    let mut parts = head.first().map(|l| l.split(' ')).into_iter().flatten();
    let (method, target) = (parts.next().unwrap_or(""), parts.next().unwrap_or(""));
    let (origin, fetch_site) = (header(&head, "origin"), header(&head, "sec-fetch-site"));
    let answer = if !site.same_origin(origin, fetch_site, header(&head, "host")) {
        Answer::text(403, "a page of another site may not ask this preview")
    } else {
        match method {
            "GET" | "HEAD" => site.answer(target, header(&head, "host")),
            _ => Answer::text(405, "only GET"),
        }
    };
    let body: &str = if method == "HEAD" { "" } else { &answer.body };
    let retry = (answer.retry_after)
        .map(|s| format!("Retry-After: {s}\r\n"))
        .unwrap_or_default();
    let head = format!(
        "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\nCache-Control: no-store\r\n\
         X-Content-Type-Options: nosniff\r\n{FRAME_POLICY}{retry}Connection: close\r\n\r\n",
        answer.status,
        reason(answer.status),
        answer.content_type,
        answer.body.len()
    );
    write_read_soon(&mut stream, head.as_bytes())?;
    write_read_soon(&mut stream, body.as_bytes())
}

/// Writes `bytes` to `stream` in pieces of [`ANSWER_PIECE`], each of which the client must
/// take within [`ANSWER_GRACE`] and its share at [`MIN_READ_BYTES_PER_SEC`]; a client that
/// reads slower is dropped.
fn write_read_soon(stream: &mut TcpStream, bytes: &[u8]) -> std::io::Result<()> {
    let per_piece =
        ANSWER_GRACE + Duration::from_secs_f64(ANSWER_PIECE as f64 / MIN_READ_BYTES_PER_SEC as f64);
    for mut piece in bytes.chunks(ANSWER_PIECE) {
        let until = Instant::now() + per_piece;
        while !piece.is_empty() {
            let left = until.saturating_duration_since(Instant::now());
            if left.is_zero() {
                return Err(std::io::ErrorKind::TimedOut.into());
            }
            stream.set_write_timeout(Some(left))?;
            let n = stream.write(piece)?;
            if n == 0 {
                return Err(std::io::ErrorKind::WriteZero.into());
            }
            piece = &piece[n..];
        }
    }
    Ok(())
}

/// What every answer's header adds to the policy each page carries in its head
/// ([`crate::render::with_policy`]): no page of the preview is framed by another site.
const FRAME_POLICY: &str =
    "Content-Security-Policy: frame-ancestors 'none'; base-uri 'none'; form-action 'none'\r\n";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slider_fields_become_json_pointers() {
        let s = |f: &str| crate::scene::Slider {
            field: f.into(),
            min: 0.0,
            max: 1.0,
            step: None,
            label: None,
        };
        assert_eq!(
            s("forces[1].angle_deg").pointer().unwrap(),
            "/forces/1/angle_deg"
        );
        assert_eq!(
            s("drawing.pole_kg[0]").pointer().unwrap(),
            "/drawing/pole_kg/0"
        );
        assert_eq!(s("a[0][2]").pointer().unwrap(), "/a/0/2");
        for bad in ["", "[0]", "a[x]", "a[0", "a]b", ".a"] {
            assert!(s(bad).pointer().is_none(), "{bad}");
        }
    }

    #[test]
    fn queries_and_names_decode() {
        assert_eq!(percent_decode("a%20b%2Fc+d"), "a b/c d");
        assert_eq!(percent_decode("100%"), "100%");
        assert_eq!(percent_encode("a b/ü"), "a%20b%2F%C3%BC");
    }
}
