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
    let mut child = Command::new(PathBuf::from(env!("CARGO_BIN_EXE_graphostatik")))
        .args(["serve", "--port", "0"])
        .arg(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut first = String::new();
    std::io::BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    let pid = child.id();
    let mut server = Server(child);
    let addr = first
        .split_whitespace()
        .find_map(|w| w.strip_prefix("http://"))
        .unwrap()
        .trim_end_matches('/')
        .to_string();
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
