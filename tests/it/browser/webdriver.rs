//! A small W3C WebDriver client over plain HTTP (std and serde_json only) for Debian's
//! `chromedriver` driving Debian's `chromium`, headless. Enough for the browser tests: open a
//! page, find elements, read text, press keys, run a script, take a screenshot and read the
//! browser's console log.

use serde_json::{json, Value};
use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// The browser and its driver, where the machine has them.
pub struct Browser {
    pub chromium: PathBuf,
    pub driver: PathBuf,
}

impl Browser {
    /// Debian's chromium and chromedriver (or those named by `CHROMIUM` and `CHROMEDRIVER`).
    pub fn find() -> Option<Browser> {
        let pick = |var: &str, default: &str| {
            let p = std::env::var_os(var)
                .map(PathBuf::from)
                .unwrap_or_else(|| PathBuf::from(default));
            p.is_file().then_some(p)
        };
        Some(Browser {
            chromium: pick("CHROMIUM", "/usr/bin/chromium")?,
            driver: pick("CHROMEDRIVER", "/usr/bin/chromedriver")?,
        })
    }
}

/// Whether a missing browser fails the test (`.ci/run` sets `GRAPHOSTATIK_BROWSER=required`
/// after installing it) or only skips it.
pub fn required() -> bool {
    std::env::var("GRAPHOSTATIK_BROWSER").is_ok_and(|v| v == "required")
}

/// A running chromedriver with one headless session.
pub struct Session {
    driver: Child,
    port: u16,
    id: String,
    profile: PathBuf,
}

fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port()
}

/// One HTTP/1.1 request to 127.0.0.1:`port`; the status and the body as JSON.
pub fn http(port: u16, method: &str, path: &str, body: Option<&Value>) -> (u16, String) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).expect("connect");
    s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
    let body = body.map(|b| b.to_string()).unwrap_or_default();
    let req = format!(
        "{method} {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Type: application/json\r\n\
         Content-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    );
    s.write_all(req.as_bytes()).unwrap();
    // The driver may keep the connection open: read the head, then the body by its length
    // (or its chunks), not to the end of the stream.
    let mut raw = Vec::new();
    let mut buf = [0u8; 65536];
    let complete = |raw: &[u8]| -> bool {
        let text = String::from_utf8_lossy(raw);
        let Some((head, rest)) = text.split_once("\r\n\r\n") else {
            return false;
        };
        let head = head.to_ascii_lowercase();
        if head.contains("transfer-encoding: chunked") {
            return rest.ends_with("0\r\n\r\n");
        }
        let len = head
            .lines()
            .find_map(|l| l.strip_prefix("content-length:"))
            .and_then(|v| v.trim().parse::<usize>().ok());
        len.is_some_and(|n| rest.len() >= n)
    };
    while !complete(&raw) {
        let n = s.read(&mut buf).unwrap();
        if n == 0 {
            break;
        }
        raw.extend_from_slice(&buf[..n]);
    }
    let text = String::from_utf8_lossy(&raw).into_owned();
    let (head, rest) = text.split_once("\r\n\r\n").unwrap_or((&text, ""));
    let status = head
        .split_whitespace()
        .nth(1)
        .and_then(|c| c.parse().ok())
        .unwrap_or(0);
    let chunked = head
        .to_ascii_lowercase()
        .contains("transfer-encoding: chunked");
    (status, if chunked { dechunk(rest) } else { rest.into() })
}

fn dechunk(mut s: &str) -> String {
    let mut out = String::new();
    while let Some((size, rest)) = s.split_once("\r\n") {
        let n = usize::from_str_radix(size.trim(), 16).unwrap_or(0);
        if n == 0 || rest.len() < n {
            break;
        }
        out.push_str(&rest[..n]);
        s = rest[n..].trim_start_matches("\r\n");
    }
    out
}

impl Session {
    /// Starts chromedriver on a free loopback port and opens a headless session with a fresh
    /// profile, the console log kept.
    pub fn start(b: &Browser, profile: &Path) -> Session {
        let port = free_port();
        let driver = Command::new(&b.driver)
            .arg(format!("--port={port}"))
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("chromedriver starts");
        let t = Instant::now();
        while TcpStream::connect(("127.0.0.1", port)).is_err() {
            assert!(t.elapsed() < Duration::from_secs(20), "chromedriver up");
            std::thread::sleep(Duration::from_millis(50));
        }
        let _ = std::fs::remove_dir_all(profile);
        let caps = json!({ "capabilities": { "alwaysMatch": {
            "browserName": "chrome",
            "goog:loggingPrefs": { "browser": "ALL" },
            "goog:chromeOptions": {
                "binary": b.chromium,
                "args": ["--headless=new", "--no-sandbox", "--disable-gpu",
                    "--disable-background-networking", "--no-first-run",
                    "--disable-dev-shm-usage", "--window-size=1400,900",
                    format!("--user-data-dir={}", profile.display())]
            }
        }}});
        let (status, body) = http(port, "POST", "/session", Some(&caps));
        assert_eq!(status, 200, "new session: {body}");
        let v: Value = serde_json::from_str(&body).unwrap();
        let id = v["value"]["sessionId"].as_str().unwrap().to_string();
        Session {
            driver,
            port,
            id,
            profile: profile.to_path_buf(),
        }
    }

    /// A command of this session; panics with the driver's message on an error.
    pub fn cmd(&self, method: &str, path: &str, body: Option<Value>) -> Value {
        let url = format!("/session/{}{path}", self.id);
        let (status, text) = http(self.port, method, &url, body.as_ref());
        let v: Value = serde_json::from_str(&text).unwrap_or(Value::Null);
        assert_eq!(status, 200, "{method} {path}: {text}");
        v["value"].clone()
    }

    pub fn goto(&self, url: &str) {
        self.cmd("POST", "/url", Some(json!({ "url": url })));
    }

    /// The element a CSS selector finds first.
    pub fn find(&self, css: &str) -> String {
        let v = self.cmd(
            "POST",
            "/element",
            Some(json!({ "using": "css selector", "value": css })),
        );
        v.as_object()
            .and_then(|o| o.values().next())
            .and_then(|e| e.as_str())
            .unwrap_or_else(|| panic!("no element {css}"))
            .to_string()
    }

    /// The visible text of the element a CSS selector finds.
    pub fn text(&self, css: &str) -> String {
        let e = self.find(css);
        self.cmd("GET", &format!("/element/{e}/text"), None)
            .as_str()
            .unwrap_or_default()
            .to_string()
    }

    /// Types keys into the page (WebDriver key codes: "\u{E014}" is →).
    pub fn keys(&self, text: &str) {
        let actions: Vec<Value> = text
            .chars()
            .flat_map(|c| {
                [
                    json!({ "type": "keyDown", "value": c.to_string() }),
                    json!({ "type": "keyUp", "value": c.to_string() }),
                ]
            })
            .collect();
        self.cmd(
            "POST",
            "/actions",
            Some(json!({ "actions": [ { "type": "key", "id": "keyboard", "actions": actions } ] })),
        );
    }

    /// Real pointer input (WebDriver actions): `press` at the viewport's pixel `from` (or not,
    /// when the button is held already), moves through `path` in steps of about 16 ms each,
    /// then releases if `release`. The pointer stays held between calls without a release.
    pub fn pointer(&self, from: Option<(f64, f64)>, path: &[(f64, f64)], release: bool) {
        let mut actions = Vec::new();
        if let Some((x, y)) = from {
            actions.push(
                json!({ "type": "pointerMove", "duration": 0, "origin": "viewport",
                "x": x.round() as i64, "y": y.round() as i64 }),
            );
            actions.push(json!({ "type": "pointerDown", "button": 0 }));
        }
        for (x, y) in path {
            actions.push(
                json!({ "type": "pointerMove", "duration": 16, "origin": "viewport",
                "x": x.round() as i64, "y": y.round() as i64 }),
            );
            actions.push(json!({ "type": "pause", "duration": 16 }));
        }
        if release {
            actions.push(json!({ "type": "pointerUp", "button": 0 }));
        }
        self.cmd(
            "POST",
            "/actions",
            Some(json!({ "actions": [ { "type": "pointer", "id": "mouse",
                "parameters": { "pointerType": "mouse" }, "actions": actions } ] })),
        );
    }

    /// Runs a script in the page and returns its value.
    pub fn script(&self, js: &str) -> Value {
        self.cmd(
            "POST",
            "/execute/sync",
            Some(json!({ "script": js, "args": [] })),
        )
    }

    /// A screenshot of the window as PNG bytes.
    pub fn screenshot(&self) -> Vec<u8> {
        let v = self.cmd("GET", "/screenshot", None);
        base64_decode(v.as_str().unwrap())
    }

    /// The console messages of level SEVERE (errors) since the last call.
    pub fn console_errors(&self) -> Vec<String> {
        let v = self.cmd("POST", "/se/log", Some(json!({ "type": "browser" })));
        v.as_array()
            .map(|a| {
                a.iter()
                    .filter(|e| e["level"] == "SEVERE")
                    .map(|e| e["message"].as_str().unwrap_or_default().to_string())
                    .collect()
            })
            .unwrap_or_default()
    }
}

/// Runs a script in the session without failing on an error (the page may be reloading):
/// the status and the body.
pub fn http_session(s: &Session, path: &str, js: &str) -> (u16, String) {
    let url = format!("/session/{}{path}", s.id);
    http(
        s.port,
        "POST",
        &url,
        Some(&json!({ "script": js, "args": [] })),
    )
}

impl Drop for Session {
    fn drop(&mut self) {
        let _ = http(self.port, "DELETE", &format!("/session/{}", self.id), None);
        let _ = self.driver.kill();
        let _ = self.driver.wait();
        let _ = std::fs::remove_dir_all(&self.profile);
    }
}

fn base64_decode(s: &str) -> Vec<u8> {
    let val = |c: u8| -> Option<u32> {
        Some(match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return None,
        } as u32)
    };
    let digits: Vec<u32> = s.bytes().filter_map(val).collect();
    let mut out = Vec::with_capacity(digits.len() * 3 / 4);
    for chunk in digits.chunks(4) {
        let mut n = 0u32;
        for (i, d) in chunk.iter().enumerate() {
            n |= d << (18 - 6 * i);
        }
        let bytes = [(n >> 16) as u8, (n >> 8) as u8, n as u8];
        out.extend_from_slice(&bytes[..chunk.len().saturating_sub(1)]);
    }
    out
}
