//! A learner's code packed for a link: deflated, then URL-safe base64, so
//! a page of code fits in an address; unpacking is bounded, so no link can
//! make the lab inflate gigabytes.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;

/// Code as link text (letters, digits, `-` and `_`).
pub fn pack(source: &str) -> String {
    let deflated = miniz_oxide::deflate::compress_to_vec(source.as_bytes(), 9);
    URL_SAFE_NO_PAD.encode(deflated)
}

/// Link text back into code, at most [`kinolab_script::MAX_SOURCE`] bytes.
pub fn unpack(text: &str) -> Result<String, String> {
    let deflated = URL_SAFE_NO_PAD
        .decode(text.trim())
        .map_err(|_| "the packed code is not URL-safe base64".to_owned())?;
    let bytes =
        miniz_oxide::inflate::decompress_to_vec_with_limit(&deflated, kinolab_script::MAX_SOURCE)
            .map_err(|_| "the packed code is damaged or too long".to_owned())?;
    String::from_utf8(bytes).map_err(|_| "the packed code is not text".to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn code_survives_packing_shorter_than_plain_base64() {
        for e in crate::all() {
            let packed = pack(e.starter);
            assert_eq!(unpack(&packed).as_deref(), Ok(e.starter));
            assert!(
                packed
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
            );
        }
        assert_eq!(unpack(&pack("")).as_deref(), Ok(""));
        // A page of code packs well under its plain base64.
        let page: String = crate::all().iter().map(|e| e.starter).collect();
        let plain = page.len().div_ceil(3) * 4;
        assert!(
            pack(&page).len() * 2 < plain,
            "{} of {plain}",
            pack(&page).len()
        );
    }

    #[test]
    fn damaged_or_huge_links_are_refused() {
        assert!(unpack("not base64!").is_err());
        assert!(unpack("AAAA").is_err());
        // A bomb: a megabyte of spaces deflates to a few hundred bytes.
        let bomb = pack(&" ".repeat(1 << 20));
        assert!(bomb.len() < 2000);
        assert!(unpack(&bomb).is_err());
    }
}
