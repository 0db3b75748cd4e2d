//! The mutations of the fuzz suite (`fuzz_models.rs`): a seeded generator and the edits of a
//! model file's text, each with a description that names the line and the change.

pub mod shared;

/// A small, fast, seeded generator (SplitMix64).
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next() % n as u64) as usize
        }
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> Option<&'a T> {
        items.get(self.below(items.len()))
    }
}

/// The quoted strings of a line (`"..."`, without escapes).
fn quoted(line: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in line.char_indices() {
        if c == '"' {
            match start {
                None => start = Some(i + 1),
                Some(s) => {
                    out.push((s, i));
                    start = None;
                }
            }
        } else if c == '#' && start.is_none() {
            break;
        }
    }
    out
}

/// The numbers of a line outside comments: byte ranges of digit runs (with a leading `.`).
fn numbers(line: &str) -> Vec<(usize, usize)> {
    let code = line.split('#').next().unwrap_or("");
    let b = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit()
            && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'));
        if starts {
            let s = i;
            while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
                i += 1;
            }
            out.push((s, i));
        } else {
            i += 1;
        }
    }
    out
}

/// The names of a model's coordinates, and of those whose unit is `rad` (its angles).
fn coordinates(text: &str) -> (Vec<String>, Vec<String>) {
    let (mut all, mut angles) = (Vec::new(), Vec::new());
    let mut in_coordinate = false;
    let mut name = None;
    for line in text.lines() {
        let t = line.trim();
        if t.starts_with('[') {
            if let Some(n) = name.take() {
                all.push(n);
            }
            in_coordinate = t == "[[coordinate]]";
        } else if in_coordinate && t.starts_with("name") {
            name = quoted(t).first().map(|&(s, e)| t[s..e].to_owned());
        } else if in_coordinate
            && t.starts_with("unit = \"rad\"")
            && let Some(n) = &name
        {
            angles.push(n.clone());
        }
    }
    (all, angles)
}

/// One mutation of `text`, and its description.
pub fn mutate(text: &str, rng: &mut Rng) -> (String, String) {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let (coords, angles) = coordinates(text);
    let angle = angles.first().cloned().unwrap_or_else(|| "x".to_owned());
    let strings: Vec<String> = lines
        .iter()
        .flat_map(|l| quoted(l).into_iter().map(move |(s, e)| l[s..e].to_owned()))
        .collect();
    let with = |lines: &[String]| lines.join("\n") + "\n";
    let n = lines.len();
    match rng.below(9) {
        0 => {
            // A number replaced.
            let candidates: Vec<usize> =
                (0..n).filter(|&i| !numbers(&lines[i]).is_empty()).collect();
            let Some(&i) = rng.pick(&candidates) else {
                return (with(&lines), "nothing".into());
            };
            let nums = numbers(&lines[i]);
            let &(s, e) = rng.pick(&nums).unwrap_or(&nums[0]);
            let long = format!("1{}", "0".repeat(400));
            let longer = format!("0.{}1", "0".repeat(5000));
            let choices = [
                "0",
                "-1",
                "-0.5",
                "1e300",
                "1e-300",
                "nan",
                "inf",
                "1e400",
                long.as_str(),
                longer.as_str(),
                "0.0000001",
                "123456789012345678901234567890",
            ];
            let v = *rng.pick(&choices).unwrap_or(&"0");
            let old = lines[i].clone();
            lines[i].replace_range(s..e, v);
            let shown: String = v.chars().take(12).collect();
            (
                with(&lines),
                format!("number: line {} `{}` -> {shown}", i + 1, old.trim()),
            )
        }
        1 => {
            // A name replaced: reserved, another's, or a duplicate.
            let candidates: Vec<usize> = (0..n)
                .filter(|&i| lines[i].trim_start().starts_with("name = "))
                .collect();
            let Some(&i) = rng.pick(&candidates) else {
                return (with(&lines), "nothing".into());
            };
            let mut names = vec![
                "sigma".to_owned(),
                "mu".to_owned(),
                "t".to_owned(),
                "g".to_owned(),
                "lambda".to_owned(),
                "q0".to_owned(),
                "x".to_owned(),
                "fn".to_owned(),
                "th\\u0007".to_owned(),
            ];
            names.extend(coords.iter().cloned());
            let v = rng.pick(&names).cloned().unwrap_or_default();
            let old = lines[i].clone();
            lines[i] = format!("name = \"{v}\"");
            (
                with(&lines),
                format!("name: line {} `{}` -> `{v}`", i + 1, old.trim()),
            )
        }
        2 => {
            let i = rng.below(n);
            let old = lines.remove(i);
            (
                with(&lines),
                format!("delete: line {} `{}`", i + 1, old.trim()),
            )
        }
        3 => {
            let i = rng.below(n);
            let copy = lines[i].clone();
            lines.insert(i, copy.clone());
            (
                with(&lines),
                format!("duplicate: line {} `{}`", i + 1, copy.trim()),
            )
        }
        4 => {
            // An expression replaced: by another of the file, a velocity, a huge multiple.
            let candidates: Vec<usize> = (0..n)
                .filter(|&i| {
                    let t = lines[i].trim_start();
                    !quoted(t).is_empty()
                        && ![
                            "name",
                            "unit",
                            "doc",
                            "title",
                            "reference",
                            "latex",
                            "format",
                            "range",
                            "point",
                            "law",
                            "friction",
                            "report",
                            "free",
                            "shape",
                        ]
                        .iter()
                        .any(|k| t.starts_with(k))
                })
                .collect();
            let Some(&i) = rng.pick(&candidates) else {
                return (with(&lines), "nothing".into());
            };
            let qs = quoted(&lines[i]);
            let &(s, e) = rng.pick(&qs).unwrap_or(&qs[0]);
            let velocity = format!("{}d", rng.pick(&coords).cloned().unwrap_or_default());
            let mut choices = vec![
                velocity,
                format!("sin(1000*{angle})"),
                format!("sin(12*{angle})"),
                format!("cos({angle}/40)"),
                "0".to_owned(),
                format!("{angle}*{angle}*{angle}^8"),
            ];
            choices.extend(rng.pick(&strings).cloned());
            let v = rng.pick(&choices).cloned().unwrap_or_default();
            let old = lines[i].clone();
            lines[i].replace_range(s..e, &v);
            (
                with(&lines),
                format!("expression: line {} `{}` -> `{v}`", i + 1, old.trim()),
            )
        }
        5 => {
            // A `[start]` value changed.
            let Some(start) = lines.iter().position(|l| l.trim() == "[start]") else {
                return (with(&lines), "nothing".into());
            };
            let end = (start + 1..n)
                .find(|&i| lines[i].trim_start().starts_with('['))
                .unwrap_or(n);
            let candidates: Vec<usize> = (start + 1..end)
                .filter(|&i| !quoted(&lines[i]).is_empty())
                .collect();
            let Some(&i) = rng.pick(&candidates) else {
                return (with(&lines), "nothing".into());
            };
            let (s, e) = quoted(&lines[i])[0];
            let choices = ["0", "1", "-1", "1e3", "-100", "1e300", "nan"];
            let v = *rng.pick(&choices).unwrap_or(&"0");
            let old = lines[i].clone();
            lines[i].replace_range(s..e, v);
            (
                with(&lines),
                format!("start: line {} `{}` -> `{v}`", i + 1, old.trim()),
            )
        }
        6 => {
            // A section duplicated.
            let headers: Vec<usize> = (0..n)
                .filter(|&i| lines[i].trim_start().starts_with('['))
                .collect();
            let Some(&i) = rng.pick(&headers) else {
                return (with(&lines), "nothing".into());
            };
            let end = (i + 1..n)
                .find(|&j| lines[j].trim_start().starts_with('['))
                .unwrap_or(n);
            let block: Vec<String> = lines[i..end].to_vec();
            lines.extend(block);
            (
                with(&lines),
                format!("section: `{}` duplicated", lines[i].trim()),
            )
        }
        7 => {
            // Extra points.
            let k = 1 + rng.below(40);
            let (x, z) = (
                coords.first().cloned().unwrap_or_default(),
                coords.get(1).cloned().unwrap_or_default(),
            );
            for j in 0..k {
                lines.push("[[point]]".into());
                lines.push(format!("name = \"extra{j}\""));
                lines.push(format!("at = [\"{x}\", \"{z}\"]"));
            }
            (with(&lines), format!("points: {k} extra"))
        }
        _ => {
            // Two mutations at once.
            let (once, a) = mutate(text, rng);
            let (twice, b) = mutate(&once, rng);
            (twice, format!("{a}; {b}"))
        }
    }
}
