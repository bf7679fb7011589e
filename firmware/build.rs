//! Linker set-up for the firmware: the board's memory map lives at the repository root
//! (`../memory.x`, shared with anything else that needs the flash layout), so copy it
//! where the linker looks, and pass the cortex-m-rt and defmt linker scripts.

use std::{env, fs, path::PathBuf};

fn main() {
    let out_dir = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let manifest_dir =
        PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let memory_x = manifest_dir.join("../memory.x");

    // cortex-m-rt's link.x does `INCLUDE memory.x`: it must be on the search path.
    fs::copy(&memory_x, out_dir.join("memory.x")).expect("copy ../memory.x to OUT_DIR");
    println!("cargo:rustc-link-search={}", out_dir.display());
    println!("cargo:rerun-if-changed={}", memory_x.display());
    println!("cargo:rerun-if-changed=build.rs");

    // Only the firmware binary is linked for the target; scripts in the order
    // cortex-m-rt documents. --nmagic: don't page-align sections (flash is tiny).
    println!("cargo:rustc-link-arg-bins=--nmagic");
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rustc-link-arg-bins=-Tdefmt.x");
}
