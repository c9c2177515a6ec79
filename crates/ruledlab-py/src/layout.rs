//! Where a number of the core's flat input came from: the argument and the NumPy index the
//! caller wrote, and the record (ruling, point, a grid's line) it belongs to as the argument's
//! leading axes count them — so that an error names `b[2, 1] (ruling 2, b.y)` and its
//! `details.index` counts what the message counts (`error.rs`). No class.

use ruledlab::Record;

/// How the flat array the core checked was laid out from the caller's arguments, to name a
/// number by the argument and the NumPy index the caller wrote, and to count records (rulings,
/// points, a grid's lines) as its leading axes count them.
pub enum Layout<'a> {
    /// The flat array is argument `name`, of `shape`, in C order; its first `lead` axes number
    /// the records.
    One {
        /// The argument.
        name: &'a str,
        /// Its shape.
        shape: Vec<usize>,
        /// How many leading axes number the records (1: rulings or points, 2: a grid).
        lead: usize,
    },
    /// Records of two arguments of shape `lead + [3]` each, interleaved: record k is `names[0][k]`
    /// then `names[1][k]`.
    Pair {
        /// The two arguments.
        names: [&'a str; 2],
        /// Their shape without the last axis.
        lead: Vec<usize>,
    },
}

/// The index of element `flat` of an array of `shape` in C order.
fn unravel(mut flat: usize, shape: &[usize]) -> Vec<usize> {
    let mut at = vec![0; shape.len()];
    for (k, &n) in shape.iter().enumerate().rev() {
        let n = n.max(1);
        at[k] = flat % n;
        flat /= n;
    }
    at
}

impl Layout<'_> {
    /// The argument and the NumPy index of number `flat` of the core's flat array.
    pub fn locate(&self, flat: usize) -> (String, Vec<usize>) {
        match self {
            Layout::One { name, shape, .. } => (name.to_string(), unravel(flat, shape)),
            Layout::Pair { names, lead } => {
                let (record, k) = (flat / 6, flat % 6);
                let mut at = unravel(record, lead);
                at.push(k % 3);
                (names[k / 3].to_string(), at)
            }
        }
    }

    /// The record of number `flat` as the leading axes count it: [ruling], [point], [row, col].
    pub fn record_of(&self, flat: usize) -> Vec<usize> {
        let (_, at) = self.locate(flat);
        let lead = match self {
            Layout::One { lead, .. } => *lead,
            Layout::Pair { lead, .. } => lead.len(),
        };
        at[..lead.min(at.len())].to_vec()
    }

    /// What the core's message should call a record: a grid's line where the records form a
    /// grid (the core's own `record` otherwise).
    pub fn record(&self, given: Record) -> Record {
        match self {
            Layout::One { shape, lead: 2, .. } if shape.len() >= 2 => Record::GridLine { cols: shape[1] },
            Layout::Pair { lead, .. } if lead.len() == 2 => Record::GridLine { cols: lead[1] },
            _ => given,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_named_by_the_argument_the_caller_wrote() {
        // number 16 of segments interleaved from a and b (N × 3 each) is b[2, 1]
        let pair = Layout::Pair { names: ["a", "b"], lead: vec![5] };
        assert_eq!(pair.locate(16), ("b".to_string(), vec![2, 1]));
        assert_eq!(pair.locate(0), ("a".to_string(), vec![0, 0]));
        // number 16 of a (rows = 2, cols = 3) grid of lines p, q: line (0, 2) → flat 12 … 17: q.y
        let grid = Layout::Pair { names: ["p", "q"], lead: vec![2, 3] };
        assert_eq!(grid.locate(16), ("q".to_string(), vec![0, 2, 1]));
        // one array of shape (N, 2, 3)
        let one = Layout::One { name: "segments", shape: vec![4, 2, 3], lead: 1 };
        assert_eq!(one.locate(16), ("segments".to_string(), vec![2, 1, 1]));
        // records counted as the message counts them: ruling 2; line (0, 2) of the grid
        assert_eq!(one.record_of(16), vec![2]);
        assert_eq!(grid.record_of(16), vec![0, 2]);
        assert_eq!(grid.record(Record::Segment), Record::GridLine { cols: 3 });
        assert_eq!(pair.record(Record::Segment), Record::Segment);
    }
}
