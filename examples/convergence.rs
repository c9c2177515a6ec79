//! Prints the convergence study of Propositions 1 and 2 for every analytic surface:
//! `cargo run --example convergence [u] [h0] [levels]`.
use ruledlab::convergence_study;
use ruledlab::AnalyticSurface;

fn main() {
    let args: Vec<f64> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let (u, h0, levels) =
        (*args.first().unwrap_or(&0.7), *args.get(1).unwrap_or(&0.1), *args.get(2).unwrap_or(&7.0) as usize);
    for s in AnalyticSurface::ALL {
        match convergence_study(&s, u, h0, levels) {
            Ok(st) => {
                println!("{} at u = {u}", s.title());
                for series in &st.series {
                    let orders: Vec<String> = series.orders.iter().map(|o| format!("{o:5.2}")).collect();
                    println!(
                        "  {:<22} expected {:.0}  fitted {:5.2}  last error {:9.2e}  orders {}",
                        series.name,
                        series.expected_order,
                        series.fitted_order,
                        series.errors.last().unwrap(),
                        orders.join(" ")
                    );
                }
            }
            Err(e) => println!("{}: {e}", s.title()),
        }
    }
}
