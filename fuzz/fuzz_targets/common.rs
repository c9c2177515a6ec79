// Shared helpers: turning fuzzer bytes into numbers that include the awkward cases.

/// f64s from the bytes, 8 at a time: raw bit patterns (NaN, ±∞, subnormals, huge values) mixed
/// with small, geometrically sensible numbers.
pub fn numbers(data: &[u8]) -> Vec<f64> {
    data.chunks_exact(8)
        .map(|c| {
            let bits = u64::from_le_bytes(c.try_into().unwrap());
            if c[0] & 1 == 0 {
                f64::from_bits(bits)
            } else {
                (bits >> 11) as f64 / (1u64 << 53) as f64 * 8.0 - 4.0
            }
        })
        .collect()
}
