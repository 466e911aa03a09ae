//! A result folder written as one transaction.
//!
//! A run (or a sweep) never writes into its target folder. It takes a lock
//! next to the target, writes the whole new set of files into a private
//! staging folder beside it, and swaps that folder in at the end with one
//! atomic rename. Whatever happens in between (a solver failure, Ctrl-C, a
//! full disk, `kill -9`, a power cut), the target is at every moment either
//! the complete old set or the complete new one, and nothing of an earlier
//! run (an old `reactions.csv`, old `vtk/*.vtp`, old `run_NNNN` folders)
//! survives into the new set.
//!
//! Layout, for the target `out/case`:
//! - `out/.case.lock`: the lock, an advisory `flock` that the kernel drops
//!   when its process dies, so a crashed run never leaves it stuck. A second
//!   run into the same folder while one is writing is refused.
//! - `out/.case.stancf-<pid>-<n>`: the staging folder. On commit it is
//!   exchanged with `out/case` (Linux `renameat2(RENAME_EXCHANGE)`, atomic
//!   even when the target exists) and the old set, now under the staging
//!   name, is deleted. Staging folders left by killed runs are deleted by
//!   the next run into the same target, under the lock.
//!
//! Where the exchange is unsupported (another OS, or a file system without
//! it), the old folder is first renamed to `out/.case.stancf-old`, then the
//! new one into place; a crash between the two renames leaves the target
//! missing with the old set intact under that name, and the next run into
//! the target (or `ResultFolder::open`) moves it back before anything else.

use crate::result_layout::{contents, Contents};
use crate::Failure;
use std::fs::{File, OpenOptions};
use std::io;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// A result folder being written: see the module documentation.
#[derive(Debug)]
pub struct ResultFolder {
    target: PathBuf,
    staging: PathBuf,
    lock: Option<Lock>,
    committed: bool,
}

/// The held lock of a target folder.
#[derive(Debug)]
struct Lock {
    path: PathBuf,
    file: File,
}

impl Drop for Lock {
    /// Unlinks the lock file while still holding it, then closes it (which
    /// releases the lock). A run that opened the same file just before the
    /// unlink finds on locking that the path no longer names its file and
    /// starts over (see [`Lock::acquire`]).
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
        let _ = self.file.unlock();
    }
}

impl Lock {
    /// Takes the lock `path` without waiting; `Ok(None)` if another process
    /// holds it.
    fn acquire(path: &Path) -> io::Result<Option<Lock>> {
        loop {
            let file = OpenOptions::new()
                .create(true)
                .truncate(false)
                .write(true)
                .open(path)?;
            match file.try_lock() {
                Ok(()) => {}
                Err(std::fs::TryLockError::WouldBlock) => return Ok(None),
                Err(std::fs::TryLockError::Error(e)) => return Err(e),
            }
            // The holder before us may have unlinked the file between our
            // open and our lock: then we hold a lock nobody else can see.
            if same_file(&file, path)? {
                return Ok(Some(Lock {
                    path: path.to_path_buf(),
                    file,
                }));
            }
        }
    }
}

#[cfg(unix)]
fn same_file(file: &File, path: &Path) -> io::Result<bool> {
    use std::os::unix::fs::MetadataExt;
    let open = file.metadata()?;
    Ok(match std::fs::metadata(path) {
        Ok(now) => now.dev() == open.dev() && now.ino() == open.ino(),
        Err(e) if e.kind() == io::ErrorKind::NotFound => false,
        Err(e) => return Err(e),
    })
}

#[cfg(not(unix))]
fn same_file(_file: &File, path: &Path) -> io::Result<bool> {
    Ok(path.exists())
}

/// Distinguishes the staging folders of several result folders opened by
/// one process (a sweep's runs).
static STAGING_COUNTER: AtomicUsize = AtomicUsize::new(0);

impl ResultFolder {
    /// Locks `target` and makes an empty staging folder beside it.
    ///
    /// Refused (exit 2, nothing written) when `target` is a file, names no
    /// folder of its own (`.`, `..`, `/`), is a dangling symbolic link,
    /// holds anything but a result set ([`crate::result_layout`]: one
    /// foreign entry is enough, and is named), is read-only or another
    /// user's, or another run is writing into it.
    pub fn open(target: &Path) -> Result<ResultFolder, Failure> {
        let target = resolve(target)?;
        let (parent, name) = split(&target)?;
        match std::fs::metadata(&target) {
            Ok(m) if !m.is_dir() => {
                return Err(Failure::Input(format!(
                    "{}: exists and is not a folder; choose another output folder",
                    target.display()
                )))
            }
            Ok(_) => {}
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                std::fs::create_dir_all(&parent).map_err(cannot(&parent))?
            }
            Err(e) => return Err(cannot(&target)(e)),
        }
        let lock_path = parent.join(format!(".{name}.lock"));
        let lock = Lock::acquire(&lock_path)
            .map_err(cannot(&lock_path))?
            .ok_or_else(|| {
                Failure::Input(format!(
                    "{}: another stancf run is writing into this folder (it holds {}); \
                     wait for it to finish or choose another output folder",
                    target.display(),
                    lock_path.display()
                ))
            })?;
        recover(&parent, &name, &target)?;
        admit_replacement(&target)?;
        remove_stale_staging(&parent, &name);
        let staging = parent.join(format!(
            "{}{}-{}",
            staging_prefix(&name),
            std::process::id(),
            STAGING_COUNTER.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::create_dir(&staging).map_err(cannot(&staging))?;
        Ok(ResultFolder {
            target,
            staging,
            lock: Some(lock),
            committed: false,
        })
    }

    /// Where the new set is written.
    pub fn staging(&self) -> &Path {
        &self.staging
    }

    /// The folder the set appears in on commit.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Swaps the staging folder in as the target, deletes the old set and
    /// releases the lock.
    ///
    /// The target is checked again first: a folder that gained a user's
    /// entry while the run wrote (or a folder a user made where there was
    /// none) is not swapped out; the new set is kept beside it under a
    /// name of its own, and the error says where. An entry that appears
    /// in the instant between that check and the swap is found in the
    /// swapped-out set, which is then kept beside the target instead of
    /// being deleted.
    pub fn commit(mut self) -> io::Result<()> {
        sync_dir(&self.staging)?;
        let exists = std::fs::symlink_metadata(&self.target).is_ok();
        if exists {
            if let Some((entry, why)) = foreign(&self.target)? {
                let kept = self.keep_beside("new-results")?;
                self.committed = true;
                return Err(io::Error::other(format!(
                    "{} appeared in the output folder while the run wrote ({why}); the folder \
                     is left as it is and the new results are in {}",
                    entry.display(),
                    kept.display()
                )));
            }
            match exchange(&self.staging, &self.target) {
                Ok(()) => {}
                Err(e) if exchange_unsupported(&e) => {
                    let (parent, name) = split(&self.target).map_err(io::Error::other)?;
                    let old = parent.join(old_name(&name));
                    std::fs::rename(&self.target, &old)?;
                    std::fs::rename(&self.staging, &self.target)?;
                    std::fs::rename(&old, &self.staging)?;
                }
                Err(e) => return Err(e),
            }
        } else {
            std::fs::rename(&self.staging, &self.target)?;
        }
        self.committed = true;
        if let Some(parent) = self.target.parent() {
            sync_dir(parent)?;
        }
        // The old set, now under the staging name (nothing if there was
        // none), deleted unless something of a user's slipped into it.
        if exists {
            if let Some((entry, why)) = foreign(&self.staging)? {
                let kept = self.keep_beside("previous")?;
                self.lock.take();
                return Err(io::Error::other(format!(
                    "the new results are in {}, but the folder they replaced held {} ({why}), \
                     which appeared while the run wrote: the replaced folder is kept as {}",
                    self.target.display(),
                    entry.display(),
                    kept.display()
                )));
            }
        }
        let _ = std::fs::remove_dir_all(&self.staging);
        self.lock.take();
        Ok(())
    }

    /// Renames the staging folder to `<name>.<what>-<pid>` beside the
    /// target (a name a user sees), which is returned.
    fn keep_beside(&self, what: &str) -> io::Result<PathBuf> {
        let (parent, name) = split(&self.target).map_err(io::Error::other)?;
        let kept = parent.join(format!("{name}.{what}-{}", std::process::id()));
        std::fs::rename(&self.staging, &kept)?;
        Ok(kept)
    }
}

impl Drop for ResultFolder {
    /// Without a commit the new set is abandoned: its staging folder is
    /// deleted (so a full disk is freed) and the target is untouched.
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.staging);
        }
    }
}

/// A symbolic link is followed: the folder it names is the target; a
/// link to nothing is refused (exit 2), naming where it points.
fn resolve(target: &Path) -> Result<PathBuf, Failure> {
    // `o/.` names the folder `o` is in to the system, though its last
    // named part is `o`: refused as `.` is (see `split`).
    let text = target.to_string_lossy();
    let trimmed = text.trim_end_matches('/');
    if trimmed == "." || trimmed.ends_with("/.") {
        return Err(Failure::Input(format!(
            "{}: not a folder name of its own (it ends in \".\"); a run replaces its output \
             folder whole, so name one (for example out/case)",
            target.display()
        )));
    }
    match std::fs::symlink_metadata(target) {
        Ok(m) if m.file_type().is_symlink() => match std::fs::canonicalize(target) {
            Ok(p) => Ok(p),
            Err(e) if e.kind() == io::ErrorKind::NotFound => Err(Failure::Input(format!(
                "{}: a symbolic link to {}, which does not exist; create that folder or \
                 choose another output folder",
                target.display(),
                std::fs::read_link(target)
                    .map(|p| p.display().to_string())
                    .unwrap_or_else(|_| "?".into())
            ))),
            Err(e) => Err(Failure::Input(format!(
                "{}: a symbolic link that cannot be followed ({e}); choose another output folder",
                target.display()
            ))),
        },
        _ => Ok(target.to_path_buf()),
    }
}

/// The parent folder and the final name of a target; a target must name a
/// folder of its own (not `.`, `..` or a root).
fn split(target: &Path) -> Result<(PathBuf, String), Failure> {
    let name = match target.components().next_back() {
        Some(std::path::Component::Normal(n)) => n.to_string_lossy().into_owned(),
        _ => {
            return Err(Failure::Input(format!(
                "{}: not a folder name of its own; a run replaces its output folder whole, \
                 so name one (for example out/case)",
                target.display()
            )))
        }
    };
    let parent = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    Ok((parent, name))
}

fn staging_prefix(name: &str) -> String {
    format!(".{name}.stancf-")
}

/// `<pid>-<n>` of a staging folder or `old` of a parked set (and nothing
/// else, so another target whose name extends this one is left alone).
fn is_staging_suffix(rest: &str) -> bool {
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    rest == "old"
        || rest
            .split_once('-')
            .is_some_and(|(a, b)| digits(a) && digits(b))
}

fn old_name(name: &str) -> String {
    format!(".{name}.stancf-old")
}

/// The first entry of the folder `dir` that is not of a result set, and
/// why; None for a result set, an empty folder or no folder.
fn foreign(dir: &Path) -> io::Result<Option<(PathBuf, String)>> {
    match contents(dir) {
        Ok(Contents::Foreign(path, why)) => Ok(Some((path, why))),
        Ok(_) => Ok(None),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(e),
    }
}

/// Whether a run may replace the existing folder `target` (nothing to do
/// when it does not exist): it must hold a result set and nothing else,
/// and each of its folders must be the user's own and writable, so that
/// the old set can be deleted once swapped out.
fn admit_replacement(target: &Path) -> Result<(), Failure> {
    let refuse = |what: String| {
        Failure::Input(format!(
            "{}: {what}; a run replaces its output folder whole, so it replaces only a folder \
             holding a result set of stancf's and nothing else: choose an empty or new folder",
            target.display()
        ))
    };
    match contents(target) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(cannot(target)(e)),
        Ok(Contents::Empty) => {}
        Ok(Contents::ResultSet) => {}
        Ok(Contents::Foreign(path, why)) => {
            return Err(refuse(format!(
                "this folder holds {} ({why})",
                path.display()
            )))
        }
    }
    match locked_folder(target).map_err(cannot(target))? {
        None => Ok(()),
        Some((path, why)) => Err(Failure::Input(format!(
            "{}: {} is {why}: the old results could not be deleted once replaced; choose \
             another output folder (or make it writable)",
            target.display(),
            path.display()
        ))),
    }
}

/// The first folder of the set under `dir` (itself included) that this
/// process may not empty: read-only by its permissions, or another user's.
#[cfg(unix)]
fn locked_folder(dir: &Path) -> io::Result<Option<(PathBuf, String)>> {
    use std::os::unix::fs::MetadataExt;
    let m = std::fs::symlink_metadata(dir)?;
    // SAFETY: geteuid(2) has no preconditions.
    let me = unsafe { libc::geteuid() };
    if m.uid() != me {
        return Ok(Some((
            dir.to_path_buf(),
            format!("owned by another user (uid {})", m.uid()),
        )));
    }
    if m.mode() & 0o200 == 0 {
        return Ok(Some((dir.to_path_buf(), "read-only".into())));
    }
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        if entry.file_type()?.is_dir() {
            if let Some(found) = locked_folder(&entry.path())? {
                return Ok(Some(found));
            }
        }
    }
    Ok(None)
}

#[cfg(not(unix))]
fn locked_folder(dir: &Path) -> io::Result<Option<(PathBuf, String)>> {
    let m = std::fs::metadata(dir)?;
    Ok(m.permissions()
        .readonly()
        .then(|| (dir.to_path_buf(), "read-only".to_string())))
}

/// Undoes a swap cut between its two renames (the fallback without
/// `RENAME_EXCHANGE`): the old set goes back under the target's name.
fn recover(parent: &Path, name: &str, target: &Path) -> Result<(), Failure> {
    let old = parent.join(old_name(name));
    if old.is_dir() && std::fs::symlink_metadata(target).is_err() {
        std::fs::rename(&old, target).map_err(cannot(target))?;
    }
    Ok(())
}

/// Deletes the staging folders of runs into this target that died (the
/// caller holds the lock, so none of them is still being written).
fn remove_stale_staging(parent: &Path, name: &str) {
    let prefix = staging_prefix(name);
    let Ok(entries) = std::fs::read_dir(parent) else {
        return;
    };
    for entry in entries.flatten() {
        let file_name = entry.file_name().to_string_lossy().into_owned();
        if file_name
            .strip_prefix(&prefix)
            .is_some_and(is_staging_suffix)
        {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}

fn cannot(path: &Path) -> impl Fn(io::Error) -> Failure + '_ {
    move |e| Failure::Other(format!("{}: cannot write results: {e}", path.display()))
}

/// Makes a folder's entries durable (a no-op where folders cannot be opened).
fn sync_dir(dir: &Path) -> io::Result<()> {
    match File::open(dir) {
        Ok(f) => f.sync_all().or(Ok(())),
        Err(_) => Ok(()),
    }
}

/// Atomically exchanges two paths (Linux `renameat2` with
/// `RENAME_EXCHANGE`).
#[cfg(target_os = "linux")]
fn exchange(a: &Path, b: &Path) -> io::Result<()> {
    use std::ffi::CString;
    use std::os::unix::ffi::OsStrExt;
    let ca = CString::new(a.as_os_str().as_bytes()).map_err(io::Error::other)?;
    let cb = CString::new(b.as_os_str().as_bytes()).map_err(io::Error::other)?;
    // SAFETY: both are valid NUL-terminated paths; AT_FDCWD resolves them
    // against the working directory as rename(2) would.
    let rc = unsafe {
        libc::renameat2(
            libc::AT_FDCWD,
            ca.as_ptr(),
            libc::AT_FDCWD,
            cb.as_ptr(),
            libc::RENAME_EXCHANGE,
        )
    };
    if rc == 0 {
        Ok(())
    } else {
        Err(io::Error::last_os_error())
    }
}

#[cfg(not(target_os = "linux"))]
fn exchange(_a: &Path, _b: &Path) -> io::Result<()> {
    Err(io::Error::from(io::ErrorKind::Unsupported))
}

/// The exchange is not available here (old kernel, file system without
/// it): fall back to two renames.
fn exchange_unsupported(e: &io::Error) -> bool {
    #[cfg(target_os = "linux")]
    if let Some(code) = e.raw_os_error() {
        return code == libc::EINVAL || code == libc::ENOSYS || code == libc::EOPNOTSUPP;
    }
    e.kind() == io::ErrorKind::Unsupported
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A summary.json of stancf's, of an older run.
    const SUMMARY_OLD: &str = r#"{"title": "old", "analysis": "static"}"#;

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("stancf-rf-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn a_commit_replaces_the_whole_old_set_and_leaves_nothing_beside_it() {
        let root = scratch("commit");
        let target = root.join("case");
        std::fs::create_dir(&target).unwrap();
        std::fs::write(target.join("summary.json"), SUMMARY_OLD).unwrap();
        std::fs::write(target.join("reactions.csv"), "old").unwrap();
        let f = ResultFolder::open(&target).unwrap();
        std::fs::write(f.staging().join("summary.json"), "new").unwrap();
        // Until the commit the old set is whole.
        assert_eq!(names(&target), ["reactions.csv", "summary.json"]);
        f.commit().unwrap();
        assert_eq!(names(&target), ["summary.json"]);
        assert_eq!(
            std::fs::read_to_string(target.join("summary.json")).unwrap(),
            "new"
        );
        assert_eq!(names(&root), ["case"]);
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn a_second_writer_is_refused_until_the_first_is_done() {
        let root = scratch("lock");
        let target = root.join("case");
        let first = ResultFolder::open(&target).unwrap();
        match ResultFolder::open(&target) {
            Err(Failure::Input(m)) => assert!(m.contains("another stancf run"), "{m}"),
            other => panic!("not refused: {other:?}"),
        }
        drop(first);
        // An abandoned set leaves neither the target nor anything beside it.
        assert!(names(&root).is_empty(), "{:?}", names(&root));
        ResultFolder::open(&target).unwrap().commit().unwrap();
        assert_eq!(names(&root), ["case"]);
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn a_folder_of_user_files_and_dot_names_are_refused() {
        let root = scratch("user");
        let target = root.join("mine");
        std::fs::create_dir(&target).unwrap();
        std::fs::write(target.join("thesis.tex"), "precious").unwrap();
        assert!(matches!(
            ResultFolder::open(&target),
            Err(Failure::Input(m)) if m.contains("thesis.tex") && m.contains("not a result set")
        ));
        for bad in [".", "..", "/", "a/..", "a/.", "./a/./", "a/./"] {
            assert!(
                matches!(ResultFolder::open(Path::new(bad)), Err(Failure::Input(_))),
                "{bad}"
            );
        }
        std::fs::write(root.join("file"), "x").unwrap();
        assert!(matches!(
            ResultFolder::open(&root.join("file")),
            Err(Failure::Input(m)) if m.contains("not a folder")
        ));
        assert_eq!(
            std::fs::read_to_string(target.join("thesis.tex")).unwrap(),
            "precious"
        );
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn staging_left_by_a_killed_run_and_a_cut_swap_are_cleaned_up() {
        let root = scratch("stale");
        let target = root.join("case");
        // A run killed while writing, and the fallback swap cut after its
        // first rename (the old set parked, no target).
        std::fs::create_dir(root.join(".case.stancf-999999-0")).unwrap();
        std::fs::create_dir(root.join(".case.stancf-old")).unwrap();
        std::fs::write(root.join(".case.stancf-old/summary.json"), SUMMARY_OLD).unwrap();
        let f = ResultFolder::open(&target).unwrap();
        assert_eq!(
            std::fs::read_to_string(target.join("summary.json")).unwrap(),
            SUMMARY_OLD
        );
        drop(f);
        assert_eq!(names(&root), ["case"]);
        std::fs::remove_dir_all(&root).unwrap();
    }
}
