//! Counts per command and verdict class, and the table the long run prints.

use std::collections::BTreeMap;
use std::time::Duration;

use crate::contract::Verdict;

/// The columns, in order.
pub const CLASSES: [&str; 7] = [
    "answer",
    "refused",
    "write failed",
    "crash",
    "hang",
    "nonsense",
    "bad error",
];

/// What a campaign saw.
#[derive(Debug, Clone, Default)]
pub struct Tally {
    counts: BTreeMap<String, [u64; 7]>,
    slowest: BTreeMap<String, Duration>,
}

impl Tally {
    pub fn add(&mut self, command: &str, verdict: &Verdict, elapsed: Duration) {
        let column = CLASSES
            .iter()
            .position(|c| *c == verdict.class())
            .unwrap_or(0);
        self.counts.entry(command.to_owned()).or_default()[column] += 1;
        let slowest = self.slowest.entry(command.to_owned()).or_default();
        *slowest = (*slowest).max(elapsed);
    }

    /// Cases of one class, all commands together.
    pub fn count(&self, class: &str) -> u64 {
        CLASSES
            .iter()
            .position(|c| *c == class)
            .map_or(0, |i| self.counts.values().map(|c| c[i]).sum())
    }

    /// Cases in all.
    pub fn total(&self) -> u64 {
        self.counts.values().flatten().sum()
    }

    /// Cases that broke the contract.
    pub fn failures(&self) -> u64 {
        self.counts
            .values()
            .map(|c| c[3..].iter().sum::<u64>())
            .sum()
    }

    /// A Markdown table: one row per command, a total row.
    pub fn table(&self) -> String {
        let mut out = String::from("| command | cases |");
        for c in CLASSES {
            out.push_str(&format!(" {c} |"));
        }
        out.push_str(" slowest |\n|---|---:|");
        out.push_str(&"---:|".repeat(CLASSES.len() + 1));
        out.push('\n');
        let mut total = [0u64; 7];
        for (command, counts) in &self.counts {
            let slowest = self.slowest.get(command).copied().unwrap_or_default();
            out.push_str(&row(
                command,
                counts,
                &format!("{:.2} s", slowest.as_secs_f64()),
            ));
            for (t, c) in total.iter_mut().zip(counts) {
                *t += c;
            }
        }
        let slowest = self.slowest.values().max().copied().unwrap_or_default();
        out.push_str(&row(
            "**all**",
            &total,
            &format!("{:.2} s", slowest.as_secs_f64()),
        ));
        out
    }
}

fn row(name: &str, counts: &[u64; 7], slowest: &str) -> String {
    let cases: u64 = counts.iter().sum();
    let mut line = format!("| {name} | {cases} |");
    for c in counts {
        line.push_str(&format!(" {c} |"));
    }
    line.push_str(&format!(" {slowest} |\n"));
    line
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_add_up() {
        let mut t = Tally::default();
        t.add("fk", &Verdict::Answer, Duration::from_millis(3));
        t.add("fk", &Verdict::Hang, Duration::from_secs(10));
        t.add("ik", &Verdict::Refused, Duration::from_millis(1));
        assert_eq!((t.total(), t.failures()), (3, 1));
        let table = t.table();
        assert!(
            table.contains("| fk | 2 | 1 | 0 | 0 | 0 | 1 | 0 | 0 | 10.00 s |"),
            "{table}"
        );
        assert!(table.contains("| **all** | 3 |"), "{table}");
    }
}
