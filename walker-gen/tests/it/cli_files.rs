//! The command line reads only regular files of bounded size and writes its output without
//! reading the target first: a device, a FIFO or a full disk gets exit code 2 and a message
//! naming the path, promptly (it used to read `/dev/zero` until memory ran out, block on a
//! FIFO for good, and read `-o /dev/full` before writing it).

use std::process::{Command, Output};
use std::time::{Duration, Instant};

/// How long a refusal of a bad input file may take: it is refused before any work, in
/// milliseconds; ten seconds leave room for a debug binary's start on a loaded machine while
/// still telling a refusal from a read without end.
const PROMPT: Duration = Duration::from_secs(10);

fn walker_gen(args: &[&str]) -> (Output, Duration) {
    let started = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_walker-gen"))
        .args(args)
        .output()
        .expect("walker-gen runs");
    (out, started.elapsed())
}

fn assert_refused(args: &[&str], fragments: &[&str]) {
    let (out, took) = walker_gen(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(took < PROMPT, "took {took:?}");
    for f in fragments {
        assert!(stderr.contains(f), "`{stderr}` lacks `{f}`");
    }
}

#[cfg(unix)]
#[test]
fn a_device_as_the_model_is_refused_before_it_is_read() {
    assert_refused(
        &["emit", "--model", "/dev/zero"],
        &["/dev/zero", "not a regular file"],
    );
    assert_refused(
        &["stats", "--scene", "/dev/zero"],
        &["/dev/zero", "not a regular file"],
    );
}

#[cfg(unix)]
#[test]
fn a_fifo_as_the_model_is_refused_without_blocking() {
    let dir = std::env::temp_dir().join(format!("walker-gen-fifo-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let fifo = dir.join("model.toml");
    let _ = std::fs::remove_file(&fifo);
    let made = Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo runs");
    assert!(made.success());
    let path = fifo.display().to_string();
    assert_refused(&["emit", "--model", &path], &[&path, "it is a FIFO"]);
    std::fs::remove_dir_all(&dir).expect("cleaned up");
}

#[cfg(target_os = "linux")]
#[test]
fn a_full_device_as_the_output_is_an_error_naming_it() {
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/../models/rimless-wheel.toml");
    let (out, _) = walker_gen(&["emit", "--model", model, "-o", "/dev/full"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("/dev/full"), "{stderr}");
}
