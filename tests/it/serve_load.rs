//! `graphostatik serve` under load on loopback: idle, slow and oversized clients beside
//! normal ones. The normal ones are served, the server stays up, its memory stays bounded,
//! and a page of another site is refused.

use std::io::{BufRead, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// `graphostatik serve` stopped when the test ends.
struct Server(std::process::Child);

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// One request's status line (or what came instead).
fn ask(addr: &str, head: &str) -> String {
    let Ok(mut s) = TcpStream::connect(addr) else {
        return "no connection".into();
    };
    s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    if s.write_all(head.as_bytes()).is_err() {
        return "write failed".into();
    }
    let mut first = String::new();
    let _ = std::io::BufReader::new(s).read_line(&mut first);
    first.trim_end().to_string()
}

fn get(addr: &str, path: &str, extra: &str) -> String {
    ask(
        addr,
        &format!("GET {path} HTTP/1.1\r\nHost: 127.0.0.1\r\n{extra}\r\n"),
    )
}

/// The server's resident memory (kB), where /proc tells it.
fn rss_kb(pid: u32) -> Option<u64> {
    let s = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = s.lines().find(|l| l.starts_with("VmRSS:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

#[test]
fn serve_stays_up_under_idle_slow_and_oversized_clients() {
    let dir = std::env::temp_dir().join(format!("gs-serve-load-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    std::fs::copy(scenes.join("lh_abb22_funicular.json"), dir.join("f.json")).unwrap();
    // A link out of the folder is not served.
    #[cfg(unix)]
    std::os::unix::fs::symlink(scenes.join("lh_abb24_beam.json"), dir.join("outside.json"))
        .unwrap();
    let (mut server, addr) = serve(&dir);
    let pid = server.0.id();
    assert!(get(&addr, "/", "").contains(" 200 "));
    let before = rss_kb(pid);

    // More idle connections than the server serves at once, and slow clients that send a
    // byte every 300 ms.
    let idle: Vec<TcpStream> = (0..300)
        .filter_map(|_| TcpStream::connect(&addr).ok())
        .collect();
    let slow: Vec<_> = (0..5)
        .map(|_| {
            let addr = addr.clone();
            std::thread::spawn(move || {
                let Ok(mut s) = TcpStream::connect(&addr) else {
                    return;
                };
                for b in b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n" {
                    if s.write_all(&[*b]).is_err() {
                        return;
                    }
                    std::thread::sleep(Duration::from_millis(300));
                }
            })
        })
        .collect();
    // A head of 2 MB with no line end: refused, not read into memory.
    let big = format!("GET /{} HTTP/1.1\r\n", "a".repeat(2 << 20));
    let answer = ask(&addr, &big);
    assert!(
        answer.starts_with("HTTP/1.1 431")
            || answer.starts_with("HTTP/1.1 503")
            || answer == "write failed",
        "{answer}"
    );
    // A normal client is served once the idle ones have had their time (HEAD_DEADLINE).
    let t = Instant::now();
    loop {
        let a = get(&addr, "/scene/f", "");
        if a.contains(" 200 ") {
            break;
        }
        // A refused connection is closed with its request unread: the client may see the
        // status line cut off after the code ("HTTP/1.1 503"), or nothing.
        assert!(a.starts_with("HTTP/1.1 503") || a.is_empty(), "{a}");
        assert!(t.elapsed() < Duration::from_secs(15), "never served: {a}");
        std::thread::sleep(Duration::from_millis(200));
    }
    drop(idle);
    for h in slow {
        h.join().unwrap();
    }
    assert!(server.0.try_wait().unwrap().is_none(), "the server is up");
    if let (Some(a), Some(b)) = (before, rss_kb(pid)) {
        assert!(b < a + 64 * 1024, "memory grew from {a} kB to {b} kB");
    }
    // Host names in any case; no page of another site; no link out of the folder.
    assert!(ask(&addr, "GET / HTTP/1.1\r\nHost: LOCALHOST\r\n\r\n").contains(" 200 "));
    assert!(get(&addr, "/scene/f", "Origin: http://evil.example\r\n").contains(" 403 "));
    assert!(get(&addr, "/scene/f", "Sec-Fetch-Site: cross-site\r\n").contains(" 403 "));
    assert!(get(&addr, "/scene/f", "Origin: http://127.0.0.1\r\n").contains(" 200 "));
    #[cfg(unix)]
    assert!(get(&addr, "/scene/outside", "").contains(" 404 "));
    let mut index = String::new();
    let mut s = TcpStream::connect(&addr).unwrap();
    s.write_all(b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
        .unwrap();
    s.read_to_string(&mut index).unwrap();
    assert!(
        !index.contains(&dir.display().to_string()),
        "the folder's path is not shown"
    );
    drop(server);
    std::fs::remove_dir_all(&dir).ok();
}

/// A server on a folder of `files` (name, scene in the repository), and its address.
fn serve_folder(tag: &str, files: &[(&str, &str)]) -> (Server, String, PathBuf) {
    let dir = std::env::temp_dir().join(format!("gs-serve-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
    for (name, from) in files {
        std::fs::copy(repo.join(from), dir.join(format!("{name}.json"))).unwrap();
    }
    let (server, addr) = serve(&dir);
    (server, addr, dir)
}

/// `graphostatik serve` on `dir` and the address it says it listens on.
fn serve(dir: &Path) -> (Server, String) {
    let mut child = Command::new(PathBuf::from(env!("CARGO_BIN_EXE_graphostatik")))
        .args(["serve", "--port", "0"])
        .arg(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut first = String::new();
    std::io::BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    let addr = first
        .split_whitespace()
        .find_map(|w| w.strip_prefix("http://"))
        .unwrap()
        .trim_end_matches('/')
        .to_string();
    (Server(child), addr)
}

/// The peak resident memory of a process (kB).
fn peak_kb(pid: u32) -> Option<u64> {
    let s = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = s.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// A GET read to its end: the status line and whether the head held `Retry-After`.
fn get_whole(addr: &str, path: &str) -> (String, bool) {
    let Ok(mut s) = TcpStream::connect(addr) else {
        return ("no connection".into(), false);
    };
    s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
    let head = format!("GET {path} HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
    if s.write_all(head.as_bytes()).is_err() {
        return ("write failed".into(), false);
    }
    let mut all = Vec::new();
    let _ = s.read_to_end(&mut all);
    let text = String::from_utf8_lossy(&all[..all.len().min(4096)]).into_owned();
    let status = text.lines().next().unwrap_or_default().to_string();
    (status, text.contains("\r\nRetry-After: "))
}

/// Asks for `path` until it is served (200), for at most `within`; the time it took.
fn served_within(addr: &str, path: &str, within: Duration) -> Duration {
    let t = Instant::now();
    loop {
        let a = get(addr, path, "");
        if a.contains(" 200 ") {
            return t.elapsed();
        }
        assert!(a.starts_with("HTTP/1.1 503") || a.is_empty(), "{a}");
        assert!(t.elapsed() < within, "not served within {within:?}: {a}");
        std::thread::sleep(Duration::from_millis(100));
    }
}

#[test]
fn serve_bounds_the_memory_of_heavy_pages_asked_at_once() {
    // Twelve scenes whose pages take some 220 MB each to build (16 cylinders at 100
    // divisions, 49,885 steps, a 30 MB page), each asked twice at once: built at once, they
    // took 2.6 GB (128 asks of one such page took over 4 GB before). They wait for the
    // budget (1 GiB, the pages kept and being sent counted in it) or are answered 503 with
    // Retry-After; a page asked by many is built
    // once, and asked again unchanged not again.
    let heavy = "tests/it/hostile/pump_16_cylinders_100_divisions.json";
    let files: Vec<(String, &str)> = (0..12).map(|k| (format!("h{k}"), heavy)).collect();
    let files: Vec<(&str, &str)> = files.iter().map(|(n, f)| (n.as_str(), *f)).collect();
    let (server, addr, dir) = serve_folder("heavy", &files);
    let pid = server.0.id();
    let answers: Vec<(String, bool)> = std::thread::scope(|s| {
        let asks: Vec<_> = (0..24)
            .map(|k| {
                let addr = &addr;
                s.spawn(move || get_whole(addr, &format!("/scene/h{}", k % 12)))
            })
            .collect();
        asks.into_iter().map(|h| h.join().unwrap()).collect()
    });
    let ok = answers.iter().filter(|(s, _)| s.contains(" 200 ")).count();
    for (status, retry) in &answers {
        assert!(
            status.contains(" 200 ") || (status.contains(" 503 ") && *retry),
            "{status}"
        );
    }
    assert!(ok >= 4, "only {ok} of 24 served: {answers:?}");
    let peak = peak_kb(pid).unwrap_or(0);
    assert!(peak < 1_400_000, "the server's memory peaked at {peak} kB");
    // Asked again, a page served is the one built: served at once.
    let t = Instant::now();
    assert!(get_whole(&addr, "/scene/h0").0.contains(" 200 "));
    assert!(get_whole(&addr, "/scene/h0").0.contains(" 200 "));
    assert!(t.elapsed() < Duration::from_secs(10), "{:?}", t.elapsed());
    assert!(server.0.id() == pid);
    drop(server);
    eprintln!(
        "{ok} of 24 served at once, the server's peak {} MB",
        peak / 1024
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn slow_readers_and_idle_clients_cannot_hold_every_slot() {
    let (mut server, addr, dir) = serve_folder(
        "slots",
        &[
            ("f", "scenes/lh_abb22_funicular.json"),
            (
                "big",
                "tests/it/hostile/pump_16_cylinders_100_divisions.json",
            ),
        ],
    );
    assert!(get_whole(&addr, "/scene/big").0.contains(" 200 "));
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    // More slow readers of the 30 MB page than the server has slots: each reads a kilobyte a
    // second, so its socket's buffers fill and the server's sends stall.
    let slow: Vec<_> = (0..140)
        .map(|_| {
            let (addr, stop) = (addr.clone(), stop.clone());
            std::thread::spawn(move || {
                let Ok(mut s) = TcpStream::connect(&addr) else {
                    return;
                };
                let head = "GET /scene/big HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
                if s.write_all(head.as_bytes()).is_err() {
                    return;
                }
                s.set_read_timeout(Some(Duration::from_secs(2))).unwrap();
                let mut buf = [0u8; 1024];
                while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                    match s.read(&mut buf) {
                        Ok(0) | Err(_) => return,
                        Ok(_) => std::thread::sleep(Duration::from_secs(1)),
                    }
                }
            })
        })
        .collect();
    std::thread::sleep(Duration::from_millis(500));
    // A normal client is served while they read: they are dropped once they fall behind
    // the floor rate (a piece of 64 KB within 2.25 s).
    let took = served_within(&addr, "/scene/f", Duration::from_secs(15));
    eprintln!("served beside 140 slow readers after {took:?}");
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    for h in slow {
        h.join().unwrap();
    }
    // Idle clients that reconnect as soon as they are closed, more than the slots: a normal
    // client takes the place of the one that waited longest.
    let running = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(true));
    let idle: Vec<_> = (0..200)
        .map(|_| {
            let (addr, running) = (addr.clone(), running.clone());
            std::thread::spawn(move || {
                let mut buf = [0u8; 64];
                while running.load(std::sync::atomic::Ordering::Relaxed) {
                    let Ok(mut s) = TcpStream::connect(&addr) else {
                        std::thread::sleep(Duration::from_millis(10));
                        continue;
                    };
                    // Wait, sending nothing, until the server closes the connection.
                    s.set_read_timeout(Some(Duration::from_millis(200)))
                        .unwrap();
                    while running.load(std::sync::atomic::Ordering::Relaxed) {
                        // Closed (0) or answered: connect again.
                        if s.read(&mut buf).is_ok() {
                            break;
                        }
                    }
                }
            })
        })
        .collect();
    std::thread::sleep(Duration::from_millis(500));
    let took = served_within(&addr, "/scene/f", Duration::from_secs(3));
    eprintln!("served beside 200 idle clients after {took:?}");
    running.store(false, std::sync::atomic::Ordering::Relaxed);
    for h in idle {
        h.join().unwrap();
    }
    // A head of the documented limit is read; one byte more is refused.
    let head = |n: usize| {
        let start = "GET /scene/f HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Pad: ";
        let pad = n - start.len() - 4;
        format!("{start}{}\r\n\r\n", "a".repeat(pad))
    };
    assert!(ask(&addr, &head(16 * 1024)).contains(" 200 "));
    assert!(ask(&addr, &head(16 * 1024 + 1)).contains(" 431 "));
    assert!(server.0.try_wait().unwrap().is_none(), "the server is up");
    drop(server);
    std::fs::remove_dir_all(&dir).ok();
}
