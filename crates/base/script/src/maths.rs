//! The numbers a script computes with: what the operators leave to
//! functions (`abs`, `min`, `floor`, conversions), and trigonometry and
//! the other transcendental functions from the lab's own maths library.
//!
//! Rhai evaluates `+ - * / % **`, comparisons and `!` itself, on integers,
//! floats and both mixed. Its arithmetic, logic and maths packages add the
//! same for nine other number types a script here never sees, at some
//! 40 kB of the lab's page; the functions below are the ones a robot's
//! code reaches for. Every transcendental function comes from the core's
//! `trig` and `libm`, so a script computes the same bits as the core,
//! natively and in wasm, and a run replays the same everywhere.

use rhai::{Engine, EvalAltResult, Position};

type Done<T> = Result<T, Box<EvalAltResult>>;

/// Register every numeric function on `e`.
pub(crate) fn register(e: &mut Engine) {
    whole_and_float(e);
    rounding(e);
    transcendental(e);
}

/// `abs`, `sign`, `min` and `max`, for integers, floats and a mix.
fn whole_and_float(e: &mut Engine) {
    e.register_fn("abs", |x: i64| {
        x.checked_abs().ok_or_else(|| overflow("abs", x))
    })
    .register_fn("abs", f64::abs)
    .register_fn("sign", i64::signum)
    .register_fn("sign", |x: f64| {
        if x == 0.0 || x.is_nan() {
            0
        } else {
            x.signum() as i64
        }
    })
    .register_fn("min", |x: i64, y: i64| x.min(y))
    .register_fn("max", |x: i64, y: i64| x.max(y))
    .register_fn("min", f64::min)
    .register_fn("max", f64::max)
    .register_fn("min", |x: i64, y: f64| (x as f64).min(y))
    .register_fn("max", |x: i64, y: f64| (x as f64).max(y))
    .register_fn("min", |x: f64, y: i64| x.min(y as f64))
    .register_fn("max", |x: f64, y: i64| x.max(y as f64))
    .register_fn("is_zero", |x: i64| x == 0)
    .register_fn("is_zero", |x: f64| x == 0.0)
    .register_fn("is_odd", |x: i64| x % 2 != 0)
    .register_fn("is_even", |x: i64| x % 2 == 0);
}

/// Rounding, the parts of a float, conversions and checks.
fn rounding(e: &mut Engine) {
    e.register_fn("floor", f64::floor)
        .register_fn("ceiling", f64::ceil)
        .register_fn("round", f64::round)
        .register_fn("int", f64::trunc)
        .register_fn("fraction", f64::fract)
        .register_fn("to_int", |x: i64| x)
        .register_fn("to_int", to_int)
        .register_fn("to_float", |x: i64| x as f64)
        .register_fn("to_float", |x: f64| x)
        .register_fn("is_nan", f64::is_nan)
        .register_fn("is_finite", f64::is_finite)
        .register_fn("is_infinite", f64::is_infinite)
        .register_fn("to_degrees", f64::to_degrees)
        .register_fn("to_radians", f64::to_radians)
        .register_fn("PI", || std::f64::consts::PI)
        .register_fn("E", || std::f64::consts::E);
}

/// A float's whole part as an integer, refused when it does not fit.
fn to_int(x: f64) -> Done<i64> {
    if x.is_nan() || x >= i64::MAX as f64 || x < i64::MIN as f64 {
        let message = format!("Integer overflow: to_int({x})");
        return Err(EvalAltResult::ErrorArithmetic(message, Position::NONE).into());
    }
    Ok(x.trunc() as i64)
}

fn overflow(what: &str, x: i64) -> Box<EvalAltResult> {
    EvalAltResult::ErrorArithmetic(format!("Integer overflow: {what}({x})"), Position::NONE).into()
}

/// `atan2(y, x)` is added beside Rhai's `atan(y, x)`.
fn transcendental(e: &mut Engine) {
    use kinolab_common::trig;
    e.register_fn("sin", trig::sin)
        .register_fn("cos", trig::cos)
        .register_fn("tan", trig::tan)
        .register_fn("atan", |y: f64, x: f64| trig::atan2(y, x))
        .register_fn("atan2", |y: f64, x: f64| trig::atan2(y, x))
        .register_fn("atan", libm::atan)
        .register_fn("asin", libm::asin)
        .register_fn("acos", libm::acos)
        .register_fn("sqrt", libm::sqrt)
        .register_fn("exp", libm::exp)
        .register_fn("ln", libm::log)
        .register_fn("log10", libm::log10)
        .register_fn("log", libm::log10)
        .register_fn("log", |x: f64, base: f64| libm::log(x) / libm::log(base))
        .register_fn("hypot", libm::hypot);
}
