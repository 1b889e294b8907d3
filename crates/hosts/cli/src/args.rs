//! Numbers and points written in options: `1,2,3`, `X,Y`, `X,Y;X,Y`.

use crate::Failure;

/// A seed for the random numbers (`--seed`): a whole number from 0 to
/// 2^64 − 1; clap shows this message after the option's name.
pub(crate) fn seed(text: &str) -> Result<u64, String> {
    text.trim()
        .parse::<u64>()
        .map_err(|_| format!("a seed is a whole number from 0 to {}", u64::MAX))
}

/// Comma-separated finite numbers; an empty text is no numbers.
pub(crate) fn numbers(option: &str, text: &str) -> Result<Vec<f64>, Failure> {
    if text.trim().is_empty() {
        return Ok(Vec::new());
    }
    text.split(',')
        .map(|part| match part.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(Failure(format!(
                "--{option}: `{}` is not a finite number",
                part.trim()
            ))),
        })
        .collect()
}

/// Exactly `N` numbers, `what` naming them for the message (`X,Y`).
pub(crate) fn fixed<const N: usize>(
    option: &str,
    what: &str,
    text: &str,
) -> Result<[f64; N], Failure> {
    let values = numbers(option, text)?;
    values.as_slice().try_into().map_err(|_| {
        let count = match N {
            1 => "one number".to_owned(),
            2 => "two numbers".to_owned(),
            3 => "three numbers".to_owned(),
            4 => "four numbers".to_owned(),
            n => format!("{n} numbers"),
        };
        Failure(format!(
            "--{option}: expected {count} {what}, got {}",
            values.len()
        ))
    })
}

/// A point `X,Y`.
pub(crate) fn point(option: &str, text: &str) -> Result<[f64; 2], Failure> {
    fixed(option, "X,Y", text)
}

/// Points `X,Y;X,Y;…` (empty groups are skipped).
pub(crate) fn points(option: &str, text: &str) -> Result<Vec<[f64; 2]>, Failure> {
    text.split(';')
        .filter(|p| !p.trim().is_empty())
        .map(|p| point(option, p))
        .collect()
}
