//! The formula checker, parser and evaluator on arbitrary text (nesting, huge numbers, unknown
//! names, unicode, the syntax of other languages): never a panic, and never deeper recursion
//! than a small stack allows. Each input runs on a thread with a 256 KiB stack, a quarter of
//! wasm's 1 MiB, so a stack that would overflow in the browser overflows here first.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ruledlab::Dual;
use ruledlab::Formula;
use ruledlab::{AnalyticCongruence, AnalyticSurface, CongruenceSpec, FormulaSpec, SmoothCongruence, SmoothRuled};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data).into_owned();
    std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(move || run(&text))
        .expect("a thread")
        .join()
        .expect("no panic");
});

fn run(text: &str) {
    // the whole text as one formula, in u and v and the parameters
    if let Ok(f) = Formula::parse("f", text, &["u", "v", "a", "b", "c"]) {
        let mut stack = Vec::new();
        for x in [0.0, -1.0, 0.5, 1e300, f64::MIN_POSITIVE] {
            let vars = [Dual::u(x), Dual::v(x), Dual::constant(1.0), Dual::constant(-2.0), Dual::constant(3.0)];
            let _ = f.eval(&vars, &mut stack);
        }
    }
    // its lines as the fields of a surface and of a congruence
    let mut parts = text.split('\n').map(str::to_string).chain(std::iter::repeat("u".to_string()));
    let mut three =
        || [parts.next().unwrap_or_default(), parts.next().unwrap_or_default(), parts.next().unwrap_or_default()];
    let (a, e, p, d) = (three(), three(), three(), three());
    let surface = FormulaSpec { a, e, u: (-1.0, 1.0), v: (-1.0, 1.0), closed: false, parameters: [1.0, 2.0, 3.0] };
    if let Ok(s) = AnalyticSurface::from_formulas(&surface) {
        let _ = s.sample(7, s.ranges());
        let _ = s.striction(0.25);
        let _ = ruledlab::convergence_study(&s, 0.1, 0.2, 4);
    }
    let congruence = CongruenceSpec { p, e: d, u: (-1.0, 1.0), v: (-1.0, 1.0), parameters: [1.0; 3], grid: (4, 3) };
    if let Ok(c) = AnalyticCongruence::from_formulas(&congruence) {
        let _ = c.grid(4, 3);
    }
}
