//! Every build tool's version, pinned here and nowhere else.
//!
//! wasm-bindgen is the one exception: its version is the `wasm-bindgen`
//! crate's in `Cargo.lock` (the CLI must match the library exactly), and
//! [`wasm_bindgen`] reads it from there.

/// Trunk builds and serves the site (0.22 needs a newer rustc).
pub const TRUNK: &str = "0.21.14";
/// wasm-pack builds the JavaScript package.
pub const WASM_PACK: &str = "0.15.1";
/// binaryen's wasm-opt, from the npm registry.
pub const BINARYEN: &str = "132.0.0";
/// A Chromium driver for the end-to-end test, using Debian's Chromium.
pub const PLAYWRIGHT_CORE: &str = "1.65.1";
/// Zopfli (in wasm, from the npm registry): the release's gzip copies.
pub const ZOPFLI: &str = "1.0.15";

/// The wasm-bindgen version pinned in Cargo.lock.
pub fn wasm_bindgen(lock: &str) -> Result<String, String> {
    let mut lines = lock.lines();
    while let Some(line) = lines.next() {
        if line == "name = \"wasm-bindgen\""
            && let Some(version) = lines.next().and_then(|l| l.strip_prefix("version = \""))
        {
            return Ok(version.trim_end_matches('"').to_owned());
        }
    }
    Err("Cargo.lock has no wasm-bindgen entry".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lock_file_names_the_wasm_bindgen_version() {
        let lock = "[[package]]\nname = \"wasm-bindgen\"\nversion = \"0.2.130\"\n";
        assert_eq!(wasm_bindgen(lock).as_deref(), Ok("0.2.130"));
        assert!(wasm_bindgen("").is_err());
    }
}
