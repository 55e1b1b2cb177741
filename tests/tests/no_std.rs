//! The no_std proof: `nostd-check/` is a `#![no_std]` staticlib with its own
//! `#[panic_handler]` linking the kernel; if anything in the kernel's dependency graph pulled
//! in `std`, rustc would reject the duplicate `panic_impl` lang item. Built here with the
//! same cargo that runs the tests.

use airlight_tests::repo_root;
use std::process::Command;

#[test]
fn kernel_links_into_a_no_std_artifact() {
    let root = repo_root();
    let out = Command::new(env!("CARGO"))
        .args(["build", "--release", "--manifest-path"])
        .arg(root.join("nostd-check/Cargo.toml"))
        .arg("--target-dir")
        .arg(root.join("target/nostd-check"))
        .output()
        .expect("run cargo");
    assert!(out.status.success(), "no_std build failed:\n{}", String::from_utf8_lossy(&out.stderr));
    let lib = root.join("target/nostd-check/release/libairlight_nostd_check.a");
    assert!(lib.exists(), "{} missing", lib.display());
}
