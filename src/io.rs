//! Writing output files whole or not at all, and never through a link someone planted.
//!
//! Every file is first written to a temporary created *exclusively* (it must not exist, and a
//! link at its name is not followed) in the target's own folder, under a name nobody can
//! predict; then renamed over the target. A rename replaces a link at the target's name
//! instead of writing through it. A [`Batch`] writes every temporary before it renames any,
//! so an error while writing (a full disk, a folder without permission) leaves every target
//! as it was; it keeps each target it replaces until the last rename has succeeded, so a
//! rename refused half-way (a sticky shared folder, an immutable file) puts back the targets
//! renamed before it. The temporaries and kept targets are the tool's own hidden names
//! (`.NAME.PID-N-KEY.tmp`, `.bak`): [`abandon`] removes those of this process (the command
//! line calls it on Ctrl-C or SIGTERM), and a batch sweeps those a process that is gone left in
//! the folders it writes.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// The temporaries and kept targets this process has made and not yet removed, and whether
/// [`abandon`] has removed them (then no more are made). A file of the tool's own is made
/// with the lock held, so that none is made unlisted.
static LIVE: Mutex<Live> = Mutex::new(Live {
    files: Vec::new(),
    abandoned: false,
});

struct Live {
    files: Vec<PathBuf>,
    abandoned: bool,
}
/// Held while a batch renames: [`abandon`] waits for the renames (and a roll-back) to end.
static RENAMING: Mutex<()> = Mutex::new(());

fn live() -> std::sync::MutexGuard<'static, Live> {
    LIVE.lock().unwrap_or_else(|e| e.into_inner())
}

fn forget(path: &Path) {
    live().files.retain(|p| p != path);
}

/// Makes a file of the tool's own at `path` by `make`, listed so that [`abandon`] finds it;
/// refused once the command is being stopped.
fn make_own<T>(path: &Path, make: impl FnOnce() -> std::io::Result<T>) -> std::io::Result<T> {
    let mut l = live();
    if l.abandoned {
        return Err(std::io::Error::new(
            std::io::ErrorKind::Interrupted,
            "the command is being stopped",
        ));
    }
    let made = make()?;
    l.files.push(path.to_path_buf());
    Ok(made)
}

/// Removes a file this process made (a temporary, a kept target) and forgets it.
fn remove_own(path: &Path) {
    let _ = std::fs::remove_file(path);
    forget(path);
}

/// Removes every temporary and kept target this process has made, after any batch renaming
/// now has finished (or rolled back): what the command line does on Ctrl-C or SIGTERM before
/// it exits, so that no hidden file is left in an output folder.
pub fn abandon() {
    let _renames = RENAMING.lock().unwrap_or_else(|e| e.into_inner());
    let mut l = live();
    l.abandoned = true;
    for p in std::mem::take(&mut l.files) {
        let _ = std::fs::remove_file(p);
    }
}

/// The largest scene file read (bytes): a file beyond it is refused before it is read.
pub const MAX_SCENE_BYTES: u64 = 256 * 1024 * 1024;

/// Reads a text file of at most `max` bytes: only a regular file (a FIFO, a device such as
/// `/dev/zero` or a folder is refused before it is opened, so it can neither block nor run
/// memory out), its size checked before it is read, and text that is not UTF-8 refused at
/// the line and column of its first bad byte.
///
/// ```
/// use graphostatik::io::read_text;
/// let e = read_text(std::path::Path::new("/dev/zero"), 1 << 20).unwrap_err();
/// assert!(e.to_string().contains("not a regular file"));
/// ```
pub fn read_text(path: &Path, max: u64) -> std::io::Result<String> {
    use std::io::{Error, ErrorKind, Read};
    let regular = |m: &std::fs::Metadata| {
        if m.is_file() {
            Ok(())
        } else {
            Err(Error::new(
                ErrorKind::InvalidInput,
                "not a regular file (a FIFO, device or folder is not read)",
            ))
        }
    };
    let too_big = |n: u64| {
        Error::new(
            ErrorKind::InvalidInput,
            format!("{n} bytes: a scene is at most {max} bytes"),
        )
    };
    let meta = std::fs::metadata(path)?;
    regular(&meta)?;
    if meta.len() > max {
        return Err(too_big(meta.len()));
    }
    let file = std::fs::File::open(path)?;
    regular(&file.metadata()?)?;
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    file.take(max + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > max {
        return Err(too_big(bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|e| {
        let b = e.as_bytes();
        let at = e.utf8_error().valid_up_to();
        let line = b[..at].iter().filter(|&&c| c == b'\n').count() + 1;
        let column = at
            - b[..at]
                .iter()
                .rposition(|&c| c == b'\n')
                .map_or(0, |i| i + 1)
            + 1;
        Error::new(
            ErrorKind::InvalidData,
            format!("{line}:{column}: not UTF-8 text (byte {at})"),
        )
    })
}

/// Writes `contents` to `path` through an exclusive temporary in the same folder and a rename,
/// so a reader (or a failed run) never sees a half-written file.
///
/// ```
/// let dir = std::env::temp_dir().join(format!("gs-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let p = dir.join("a.svg");
/// graphostatik::io::write_atomic(&p, "<svg/>").unwrap();
/// assert_eq!(std::fs::read_to_string(&p).unwrap(), "<svg/>");
/// std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn write_atomic(path: &Path, contents: &str) -> std::io::Result<()> {
    let mut batch = Batch::default();
    batch.add(path, contents.to_string());
    batch.commit().map_err(|e| e.source)
}

/// A write of one file of a batch that failed: which file, and why.
#[derive(Debug)]
pub struct BatchError {
    /// The target the error is about.
    pub path: PathBuf,
    /// The operating system's error.
    pub source: std::io::Error,
}

impl std::fmt::Display for BatchError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: cannot write: {}", self.path.display(), self.source)
    }
}

impl std::error::Error for BatchError {}

/// Files written all or none: [`Batch::commit`] writes every temporary first; if one fails,
/// it removes them all and no target changes. Only then are they renamed over their targets.
///
/// ```
/// use graphostatik::io::Batch;
/// let dir = std::env::temp_dir().join(format!("gs-batch-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let mut b = Batch::default();
/// b.add(dir.join("a.svg"), "<svg/>".into());
/// b.add(dir.join("no/such/folder/b.svg"), "<svg/>".into());
/// assert!(b.commit().is_err());
/// assert!(!dir.join("a.svg").exists()); // all or nothing
/// std::fs::remove_dir_all(&dir).unwrap();
/// ```
#[derive(Debug, Default)]
pub struct Batch {
    files: Vec<(PathBuf, Vec<u8>)>,
}

impl Batch {
    /// Adds a file to write.
    pub fn add(&mut self, path: impl Into<PathBuf>, contents: String) {
        self.files.push((path.into(), contents.into_bytes()));
    }

    /// Adds a file of bytes to write (a PNG, a PDF).
    pub fn add_bytes(&mut self, path: impl Into<PathBuf>, contents: Vec<u8>) {
        self.files.push((path.into(), contents));
    }

    /// The targets, in the order added.
    pub fn paths(&self) -> impl Iterator<Item = &Path> {
        self.files.iter().map(|(p, _)| p.as_path())
    }

    /// The number of bytes the batch writes.
    pub fn bytes(&self) -> usize {
        self.files.iter().map(|(_, c)| c.len()).sum()
    }

    /// Only a regular file (or a link, which the rename replaces) is written over: a folder,
    /// a device such as /dev/null, a FIFO or a socket is refused before anything is written.
    fn check_kinds(&self) -> Result<(), BatchError> {
        for (path, _) in &self.files {
            let Ok(m) = std::fs::symlink_metadata(path) else {
                continue;
            };
            let what = if m.is_dir() {
                "a folder has this name"
            } else if m.is_file() || m.file_type().is_symlink() {
                continue;
            } else {
                "not a regular file (a device, FIFO or socket is not written over)"
            };
            return Err(BatchError {
                path: path.clone(),
                source: std::io::Error::new(std::io::ErrorKind::AlreadyExists, what),
            });
        }
        Ok(())
    }

    /// Whether every file could be written, tried before the work that makes them: each
    /// target's kind ([`Batch::commit`]'s rule) and an empty temporary made and removed in
    /// each folder. A command that runs long checks its outputs first, so it does not fail
    /// at the end for a missing folder.
    pub fn check_targets(paths: &[&Path]) -> Result<(), BatchError> {
        let probe = Batch {
            files: paths
                .iter()
                .map(|p| (p.to_path_buf(), Vec::new()))
                .collect(),
        };
        probe.check_kinds()?;
        for p in paths {
            let tmp = write_temporary(p, &[]).map_err(|source| BatchError {
                path: p.to_path_buf(),
                source,
            })?;
            remove_own(&tmp);
        }
        Ok(())
    }

    /// Writes every file: all temporaries first, made durable together (one sync of their
    /// file system), then the renames, then the folders synced so the renames last too.
    /// Each target replaced is kept (a hard link, or a copy where the file system has none)
    /// until every rename has succeeded; a rename refused half-way puts the targets renamed
    /// before it back and removes the new ones. A replaced file keeps its permissions.
    /// Temporaries a process that is gone left in the batch's folders are removed first.
    ///
    /// # Errors
    /// The first file that could not be written; then no target has changed.
    pub fn commit(self) -> Result<(), BatchError> {
        self.check_kinds()?;
        sweep_stale(self.files.iter().map(|(p, _)| p.as_path()));
        let mut temps: Vec<(PathBuf, &Path)> = Vec::with_capacity(self.files.len());
        let mut failed = None;
        for (path, contents) in &self.files {
            match write_temporary(path, contents) {
                Ok(tmp) => temps.push((tmp, path)),
                Err(source) => {
                    failed = Some(BatchError {
                        path: path.clone(),
                        source,
                    });
                    break;
                }
            }
        }
        let remove_all = |temps: &[(PathBuf, &Path)]| {
            for (tmp, _) in temps {
                remove_own(tmp);
            }
        };
        if let Some(e) = failed {
            remove_all(&temps);
            return Err(e);
        }
        if let Err(e) = make_durable(&temps) {
            remove_all(&temps);
            return Err(e);
        }
        let renamed = {
            let _renames = RENAMING.lock().unwrap_or_else(|e| e.into_inner());
            rename_all_or_none(&temps)
        };
        renamed?;
        sync_folders(temps.iter().map(|(_, p)| *p))
    }
}

/// Renames each temporary over its target, keeping each target it replaces; on the first
/// refusal, the targets renamed before are put back (or removed, where there was none) and
/// every temporary is removed. The kept targets are removed at the end either way.
fn rename_all_or_none(temps: &[(PathBuf, &Path)]) -> Result<(), BatchError> {
    // What each target was: its kept copy, or none where there was no target.
    let mut done: Vec<(&Path, Option<PathBuf>)> = Vec::with_capacity(temps.len());
    let mut result = Ok(());
    for (tmp, path) in temps {
        let kept = match keep_target(path) {
            Ok(k) => k,
            Err(source) => {
                result = Err(BatchError {
                    path: path.to_path_buf(),
                    source,
                });
                break;
            }
        };
        if let Err(source) = std::fs::rename(tmp, path) {
            if let Some(k) = &kept {
                remove_own(k);
            }
            result = Err(BatchError {
                path: path.to_path_buf(),
                source,
            });
            break;
        }
        forget(tmp);
        done.push((path, kept));
    }
    if result.is_err() {
        for (path, kept) in done.iter().rev() {
            match kept {
                Some(k) => {
                    if std::fs::rename(k, path).is_ok() {
                        forget(k);
                    }
                }
                None => {
                    let _ = std::fs::remove_file(path);
                }
            }
        }
        for (tmp, _) in temps {
            remove_own(tmp);
        }
    }
    for (_, kept) in &done {
        if let Some(k) = kept {
            remove_own(k);
        }
    }
    result
}

/// A copy of the target at `path` kept beside it under a hidden name of the tool's own (a
/// hard link; a copy where the file system makes none), or `None` where there is no target
/// (a link at the target's name is not kept: the rename replaces the link, and a roll-back
/// removes the new file).
fn keep_target(path: &Path) -> std::io::Result<Option<PathBuf>> {
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.is_file() => {}
        _ => return Ok(None),
    }
    let name = own_name(path, "bak");
    if make_own(&name, || std::fs::hard_link(path, &name)).is_err() {
        let mut options = std::fs::OpenOptions::new();
        options.write(true).create_new(true);
        let mut to = make_own(&name, || options.open(&name))?;
        let copied =
            std::fs::File::open(path).and_then(|mut from| std::io::copy(&mut from, &mut to));
        if let Err(e) = copied {
            remove_own(&name);
            return Err(e);
        }
        let _ = std::fs::set_permissions(&name, std::fs::metadata(path)?.permissions());
    }
    Ok(Some(name))
}

/// Removes, from each folder the targets are in, the temporaries and kept targets that a
/// process now gone left behind (killed while it wrote): only names of the tool's own form
/// (`.NAME.PID-N-KEY.tmp` or `.bak`) of a regular file, and only on Linux, where a process's
/// presence can be asked (`/proc/PID`).
fn sweep_stale<'a>(targets: impl Iterator<Item = &'a Path>) {
    if !cfg!(target_os = "linux") {
        return;
    }
    // By folder, the names this batch writes there (as a temporary's name carries them).
    let mut folders: std::collections::BTreeMap<&Path, Vec<String>> = Default::default();
    for t in targets {
        let name = t.file_name().map(|n| n.to_string_lossy().into_owned());
        let name = name.unwrap_or_else(|| "out".into());
        (folders.entry(folder(t)).or_default()).push(kept_bytes(&name).to_string());
    }
    for (dir, names) in folders {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        for e in entries.flatten() {
            let name = e.file_name();
            let Some((target, pid)) = name.to_str().and_then(own_name_parts) else {
                continue;
            };
            // Only a temporary of a file this batch writes, left an hour ago or more by a
            // process this system does not know (one in another PID namespace, writing into
            // a shared folder, has fresh files).
            let ours = names.iter().any(|n| n == target);
            let old = (e.metadata().and_then(|m| m.modified()))
                .ok()
                .and_then(|t| t.elapsed().ok())
                .is_some_and(|age| age >= STALE_AFTER);
            let gone = !Path::new(&format!("/proc/{pid}")).exists();
            if ours && old && gone && e.file_type().is_ok_and(|t| t.is_file()) {
                let _ = std::fs::remove_file(e.path());
            }
        }
    }
}

/// How old a temporary of a process that is gone must be before a batch removes it.
pub const STALE_AFTER: std::time::Duration = std::time::Duration::from_secs(3600);

/// The target's name and the process of a name of the tool's own form (`.NAME.PID-N-KEY.tmp`
/// or `.bak`, KEY 16 hex digits), if `name` is one.
fn own_name_parts(name: &str) -> Option<(&str, u32)> {
    let rest = name.strip_prefix('.')?;
    let rest = rest
        .strip_suffix(".tmp")
        .or_else(|| rest.strip_suffix(".bak"))?;
    let (target, tag) = rest.rsplit_once('.')?;
    let mut parts = tag.split('-');
    let (pid, n, key) = (parts.next()?, parts.next()?, parts.next()?);
    let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    let ok = parts.next().is_none()
        && digits(n)
        && key.len() == 16
        && key.bytes().all(|b| b.is_ascii_hexdigit());
    ok.then(|| pid.parse().ok()).flatten().map(|p| (target, p))
}

/// The part of a target's name a temporary's name carries ([`NAME_BYTES_KEPT`]).
fn kept_bytes(target: &str) -> &str {
    let mut cut = target.len().min(NAME_BYTES_KEPT);
    while !target.is_char_boundary(cut) {
        cut -= 1;
    }
    &target[..cut]
}

/// The folder a target is written in.
fn folder(path: &Path) -> &Path {
    path.parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
}

/// The temporaries' contents on the disk before any is renamed over its target, so that a
/// crash leaves each target old or new, never empty. One file is synced by itself; a batch by
/// one `syncfs` per file system it writes to (an `fsync` per file tripled the time of
/// rendering a folder of figures on a slow disk). Elsewhere than on Linux, each file's own sync.
fn make_durable(temps: &[(PathBuf, &Path)]) -> Result<(), BatchError> {
    let failed = |path: &Path| {
        let path = path.to_path_buf();
        move |source| BatchError { path, source }
    };
    #[cfg(target_os = "linux")]
    if temps.len() > 1 {
        use std::os::unix::fs::MetadataExt;
        // A temporary lives on the file system of the folder it was made in: each folder
        // opened once (not each of its files), each file system synced once.
        let folders: std::collections::BTreeMap<&Path, &Path> = temps
            .iter()
            .map(|(_, path)| (folder(path), *path))
            .collect();
        let mut devices = std::collections::BTreeSet::new();
        for (dir, path) in folders {
            let f = std::fs::File::open(dir).map_err(failed(path))?;
            let device = f.metadata().map_err(failed(path))?.dev();
            if devices.insert(device) {
                rustix::fs::syncfs(&f).map_err(|e| failed(path)(e.into()))?;
            }
        }
        return Ok(());
    }
    for (tmp, path) in temps {
        let f = std::fs::OpenOptions::new().write(true).open(tmp);
        f.and_then(|f| f.sync_all()).map_err(failed(path))?;
    }
    Ok(())
}

/// Each folder written to synced once, so that its renames survive a crash (Unix; elsewhere a
/// folder cannot be opened to sync it, and the file system keeps its own order).
fn sync_folders<'a>(targets: impl Iterator<Item = &'a Path>) -> Result<(), BatchError> {
    let folders: std::collections::BTreeSet<&Path> = targets.map(folder).collect();
    if cfg!(unix) {
        for dir in folders {
            let synced = std::fs::File::open(dir).and_then(|d| d.sync_all());
            synced.map_err(|source| BatchError {
                path: dir.to_path_buf(),
                source,
            })?;
        }
    }
    Ok(())
}

/// Most bytes of the target's name a temporary's name carries: with the rest
/// (`.`, `.PID-N-KEY.tmp`, up to 50 bytes) it stays within a file system's 255.
const NAME_BYTES_KEPT: usize = 120;

/// A name no other writer can guess in advance: the target's name (its first
/// [`NAME_BYTES_KEPT`] bytes), the process, a counter, and a random key (std's randomly seeded
/// hasher over the counter and the clock), ending in `.kind`.
fn temporary_name(target: &str, kind: &str) -> String {
    use std::hash::BuildHasher;
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let t = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    let key = std::collections::hash_map::RandomState::new().hash_one((n, t));
    format!(
        ".{}.{}-{n}-{key:016x}.{kind}",
        kept_bytes(target),
        std::process::id()
    )
}

/// A fresh name of the tool's own beside `path`, ending in `.kind`.
fn own_name(path: &Path, kind: &str) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".into());
    folder(path).join(temporary_name(&name, kind))
}

/// Writes `contents` to a fresh temporary beside `path`, created exclusively and without
/// following a link; returns its path.
fn write_temporary(path: &Path, contents: &[u8]) -> std::io::Result<PathBuf> {
    // A replaced file keeps its permissions (but a set-user or set-group bit) and, where this
    // process may give it, its owner; a new one is 644 less the umask.
    let replaced = match std::fs::symlink_metadata(path) {
        Ok(m) if m.is_file() => Some(m),
        _ => None,
    };
    for _ in 0..16 {
        let tmp = own_name(path, "tmp");
        let mut options = std::fs::OpenOptions::new();
        options.write(true).create_new(true);
        // create_new is O_CREAT | O_EXCL: it fails on an existing name, a link included,
        // and never opens what a link points to.
        #[cfg(unix)]
        {
            use std::os::unix::fs::OpenOptionsExt;
            options.mode(0o644);
        }
        let mut f = match make_own(&tmp, || options.open(&tmp)) {
            Ok(f) => f,
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        };
        let written = match &replaced {
            Some(m) => keep_owner_and_mode(&f, m),
            None => Ok(()),
        }
        .and_then(|()| f.write_all(contents));
        if let Err(e) = written {
            remove_own(&tmp);
            return Err(e);
        }
        return Ok(tmp);
    }
    Err(std::io::Error::new(
        std::io::ErrorKind::AlreadyExists,
        "no free temporary name in the output folder",
    ))
}

/// Gives the open temporary `f` the owner (where this process may: as root) and the mode of
/// the file it replaces, less a set-user, set-group or sticky bit.
fn keep_owner_and_mode(f: &std::fs::File, target: &std::fs::Metadata) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::{MetadataExt, PermissionsExt};
        let _ = std::os::unix::fs::fchown(f, Some(target.uid()), Some(target.gid()));
        f.set_permissions(std::fs::Permissions::from_mode(target.mode() & 0o777))
    }
    #[cfg(not(unix))]
    f.set_permissions(target.permissions())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("gs-io-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn temporary_names_differ_every_time() {
        let a = temporary_name("a.svg", "tmp");
        let b = temporary_name("a.svg", "tmp");
        assert_ne!(a, b);
        assert!(a.starts_with(".a.svg.") && a.ends_with(".tmp"));
    }

    #[cfg(unix)]
    #[test]
    fn a_link_at_the_target_is_replaced_not_written_through() {
        let d = dir("link");
        let outside = d.join("outside.txt");
        std::fs::write(&outside, "keep").unwrap();
        let out = d.join("out");
        std::fs::create_dir_all(&out).unwrap();
        std::os::unix::fs::symlink(&outside, out.join("a.svg")).unwrap();
        // And links at the names the old writer would have used.
        let old = out.join(format!(".a.svg.tmp-{}", std::process::id()));
        std::os::unix::fs::symlink(&outside, &old).unwrap();
        write_atomic(&out.join("a.svg"), "<svg/>").unwrap();
        assert_eq!(std::fs::read_to_string(&outside).unwrap(), "keep");
        assert_eq!(
            std::fs::read_to_string(out.join("a.svg")).unwrap(),
            "<svg/>"
        );
        assert!(!std::fs::symlink_metadata(out.join("a.svg"))
            .unwrap()
            .file_type()
            .is_symlink());
        std::fs::remove_dir_all(&d).unwrap();
    }

    /// A rename refused half-way (here the second temporary is gone) puts the first target
    /// back as it was and removes what it made.
    #[test]
    fn a_rename_refused_half_way_puts_back_the_targets_renamed_before() {
        let d = dir("halfway");
        std::fs::write(d.join("a.svg"), "old a").unwrap();
        let a = write_temporary(&d.join("a.svg"), b"new a").unwrap();
        let b = write_temporary(&d.join("b.svg"), b"new b").unwrap();
        let c = write_temporary(&d.join("c.svg"), b"new c").unwrap();
        std::fs::remove_file(&b).unwrap();
        let (pa, pb, pc) = (d.join("a.svg"), d.join("b.svg"), d.join("c.svg"));
        let temps = vec![(a, pa.as_path()), (b, pb.as_path()), (c, pc.as_path())];
        let e = rename_all_or_none(&temps).unwrap_err();
        assert!(e.path.ends_with("b.svg"), "{e}");
        assert_eq!(std::fs::read_to_string(&pa).unwrap(), "old a");
        let left: Vec<_> = std::fs::read_dir(&d)
            .unwrap()
            .flatten()
            .map(|e| e.file_name())
            .collect();
        assert_eq!(left, ["a.svg"], "nothing else is left");
        std::fs::remove_dir_all(&d).unwrap();
    }

    /// A replaced file keeps its mode; a target's name of 250 bytes is written (its
    /// temporary's name is cut); what a process now gone left is swept, and nothing else.
    #[test]
    fn modes_long_names_and_stale_temporaries() {
        let d = dir("modes");
        let target = d.join("kept.svg");
        std::fs::write(&target, "old").unwrap();
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o600)).unwrap();
        }
        let long = d.join(format!("{}.svg", "a".repeat(246)));
        // pid 999999999 is past every kernel's pid_max: no such process.
        let stale = d.join(".kept.svg.999999999-1-0123456789abcdef.tmp");
        let decoy = d.join(".kept.svg.999999999-1-notours.tmp");
        // A fresh one (a process in another PID namespace may be writing it) and one of a
        // file this batch does not write stay, however old.
        let fresh = d.join(".kept.svg.999999998-1-0123456789abcdef.tmp");
        let other = d.join(".holiday.jpg.999999999-0-0123456789abcdef.tmp");
        for f in [&stale, &decoy, &fresh, &other] {
            std::fs::write(f, "").unwrap();
        }
        let hours_ago = std::time::SystemTime::now() - 2 * STALE_AFTER;
        for f in [&stale, &other] {
            let file = std::fs::File::options().write(true).open(f).unwrap();
            file.set_modified(hours_ago).unwrap();
        }
        let mut b = Batch::default();
        b.add(&target, "new".into());
        b.add(&long, "long".into());
        b.commit().unwrap();
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "new");
        assert_eq!(std::fs::read_to_string(&long).unwrap(), "long");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(&target).unwrap().permissions().mode();
            assert_eq!(mode & 0o777, 0o600);
        }
        assert_eq!(stale.exists(), !cfg!(target_os = "linux"));
        assert!(decoy.exists() && fresh.exists() && other.exists());
        assert_eq!(
            own_name_parts(".a.svg.12-3-0123456789abcdef.bak"),
            Some(("a.svg", 12))
        );
        assert_eq!(own_name_parts(".a.svg.12-3-0123456789abcdef.txt"), None);
        assert_eq!(own_name_parts("a.svg.12-3-0123456789abcdef.tmp"), None);
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_failed_batch_changes_nothing_and_leaves_no_temporaries() {
        let d = dir("batch");
        std::fs::write(d.join("a.svg"), "old").unwrap();
        let mut b = Batch::default();
        b.add(d.join("a.svg"), "new".into());
        b.add(d.join("missing").join("b.svg"), "new".into());
        let e = b.commit().unwrap_err();
        assert!(e.path.ends_with("missing/b.svg"), "{e}");
        assert_eq!(std::fs::read_to_string(d.join("a.svg")).unwrap(), "old");
        let left: Vec<_> = std::fs::read_dir(&d).unwrap().collect();
        assert_eq!(left.len(), 1, "only a.svg is there");
        std::fs::remove_dir_all(&d).unwrap();
    }
}

/// The memory this machine has free for new work (bytes): Linux's `MemAvailable`; `None`
/// where it cannot be read (another system, no `/proc`).
pub fn available_memory() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    memory_available_in(&text)
}

/// `MemAvailable` of a `/proc/meminfo` text, in bytes.
fn memory_available_in(meminfo: &str) -> Option<u64> {
    let line = meminfo.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    kb.checked_mul(1024)
}

#[cfg(test)]
mod memory_tests {
    #[test]
    fn reads_what_the_kernel_says_is_available() {
        let text = "MemTotal:       24684544 kB\nMemFree:        18083000 kB\nMemAvailable:   22959104 kB\n";
        assert_eq!(super::memory_available_in(text), Some(22_959_104 * 1024));
        assert_eq!(super::memory_available_in("MemTotal: 1 kB\n"), None);
        assert_eq!(super::memory_available_in("MemAvailable: lots kB\n"), None);
        if cfg!(target_os = "linux") {
            assert!(super::available_memory().is_some_and(|b| b > 0));
        }
    }
}
