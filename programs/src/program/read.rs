//! Small readers of each family's joint targets: they take a written program apart
//! by the controller language's own syntax (not by the writer's code) and give every
//! joint move's target, in the controller's joint degrees, with the dwell and the
//! operator stop (its message) that follow it. The tests read every program back
//! through them.

use std::collections::HashMap;

/// One joint move read back.
#[derive(Clone, Debug, PartialEq)]
pub struct ReadMove {
    /// Its target, in the controller's joint degrees.
    pub joints_deg: [f64; 6],
    /// The wait right after it (s), if any.
    pub dwell_s: Option<f64>,
    /// The message of the stop for the operator after it, before the next move, if
    /// any (the message's pieces joined by spaces).
    pub stop: Option<String>,
}

fn six(values: &[f64], what: &str) -> Result<[f64; 6], String> {
    <[f64; 6]>::try_from(values).map_err(|_| format!("{what}: {} values, expected 6", values.len()))
}

fn number(s: &str, what: &str) -> Result<f64, String> {
    s.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("{what}: '{s}' is not a number"))
}

/// The text between `open` and the next `close` after it.
fn between<'a>(s: &'a str, open: &str, close: &str) -> Option<&'a str> {
    let start = s.find(open)? + open.len();
    let end = s[start..].find(close)? + start;
    Some(&s[start..end])
}

fn dwell(moves: &mut [ReadMove], t: f64, line: usize) -> Result<(), String> {
    match moves.last_mut() {
        Some(m) if m.dwell_s.is_none() => {
            m.dwell_s = Some(t);
            Ok(())
        }
        Some(_) => Err(format!("line {line}: a second wait after one move")),
        None => Err(format!("line {line}: a wait before any move")),
    }
}

fn stop(moves: &mut [ReadMove], message: &[String], line: usize) -> Result<(), String> {
    match moves.last_mut() {
        Some(m) if m.stop.is_none() => {
            m.stop = Some(message.join(" "));
            Ok(())
        }
        Some(_) => Err(format!("line {line}: a second stop after one move")),
        None => Err(format!("line {line}: a stop before any move")),
    }
}

/// KRL: `PTP {AXIS: A1 v,A2 v,…}`, `WAIT SEC t` and `HALT`, whose message is the
/// comment lines right above it (case-insensitive; `;` starts a comment).
///
/// # Errors
/// A malformed target or wait, naming the line.
pub fn krl(text: &str) -> Result<Vec<ReadMove>, String> {
    let mut moves = Vec::new();
    let mut comments: Vec<String> = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        if let Some(c) = raw.trim().strip_prefix(';') {
            comments.push(c.trim().to_owned());
            continue;
        }
        let above = std::mem::take(&mut comments);
        let line = raw.split(';').next().unwrap_or("").trim();
        let upper = line.to_ascii_uppercase();
        if upper == "HALT" {
            stop(&mut moves, &above, i + 1)?;
        } else if upper.starts_with("PTP") && upper.contains("{AXIS:") {
            let inner = between(&upper, "{AXIS:", "}")
                .ok_or(format!("line {}: no closing brace", i + 1))?;
            let mut q = [f64::NAN; 6];
            for item in inner.split(',') {
                let mut it = item.split_whitespace();
                let (Some(axis), Some(v)) = (it.next(), it.next()) else {
                    return Err(format!("line {}: '{item}' is not 'An value'", i + 1));
                };
                let k: usize = axis
                    .strip_prefix('A')
                    .and_then(|n| n.parse().ok())
                    .filter(|k| (1..=6).contains(k))
                    .ok_or(format!("line {}: '{axis}' is not A1-A6", i + 1))?;
                q[k - 1] = number(v, &format!("line {}", i + 1))?;
            }
            if q.iter().any(|v| v.is_nan()) {
                return Err(format!("line {}: not all of A1-A6", i + 1));
            }
            moves.push(ReadMove {
                joints_deg: q,
                dwell_s: None,
                stop: None,
            });
        } else if let Some(t) = upper.strip_prefix("WAIT SEC") {
            dwell(&mut moves, number(t, &format!("line {}", i + 1))?, i + 1)?;
        }
    }
    Ok(moves)
}

/// RAPID: `CONST jointtarget name:=[[6 values],[…]];`, `MoveAbsJ name,…;`,
/// `WaitTime t;` and `STOP;`, whose message is the `TPWrite "…";` lines right above
/// it (`!` starts a comment).
///
/// # Errors
/// A malformed target, a move to an undeclared target, naming the line.
pub fn rapid(text: &str) -> Result<Vec<ReadMove>, String> {
    let mut targets: HashMap<String, [f64; 6]> = HashMap::new();
    let mut moves = Vec::new();
    let mut written: Vec<String> = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.split('!').next().unwrap_or("").trim();
        let at = format!("line {}", i + 1);
        if line.is_empty() {
            continue;
        }
        if let Some(rest) = line.strip_prefix("TPWrite ") {
            let s = between(rest, "\"", "\"").ok_or(format!("{at}: TPWrite without a string"))?;
            written.push(s.to_owned());
            continue;
        }
        let above = std::mem::take(&mut written);
        if line == "STOP;" {
            stop(&mut moves, &above, i + 1)?;
        } else if let Some(rest) = line.strip_prefix("CONST jointtarget ") {
            let (name, value) = rest.split_once(":=").ok_or(format!("{at}: no ':='"))?;
            let robax = between(value, "[[", "]").ok_or(format!("{at}: no [[robax]"))?;
            let v: Vec<f64> = robax
                .split(',')
                .map(|x| number(x, &at))
                .collect::<Result<_, _>>()?;
            targets.insert(name.trim().to_owned(), six(&v, &at)?);
        } else if let Some(rest) = line.strip_prefix("MoveAbsJ ") {
            let name = rest.split([',', '\\', ' ']).next().unwrap_or("").trim();
            let q = targets
                .get(name)
                .ok_or(format!("{at}: target '{name}' is not declared above"))?;
            moves.push(ReadMove {
                joints_deg: *q,
                dwell_s: None,
                stop: None,
            });
        } else if let Some(rest) = line.strip_prefix("WaitTime ") {
            dwell(&mut moves, number(rest.trim_end_matches(';'), &at)?, i + 1)?;
        }
    }
    Ok(moves)
}

/// FANUC LS: `/MN` lines `J P[n] …`, `WAIT t(sec)` and `PAUSE`, whose message is the
/// `MESSAGE[…]` lines right above it; `/POS` points `P[n]{ … J1= v deg, … }`.
///
/// # Errors
/// A malformed line or point, a move to a point `/POS` does not hold.
pub fn tp(text: &str) -> Result<Vec<ReadMove>, String> {
    let (main, pos) = text.split_once("/POS").ok_or("no /POS section")?;
    let mut points: HashMap<usize, [f64; 6]> = HashMap::new();
    for block in pos.split("P[").skip(1) {
        let (n, body) = block.split_once(']').ok_or("a point without ']'")?;
        let n: usize = n
            .trim()
            .parse()
            .map_err(|_| format!("P[{n}]: not a number"))?;
        let mut q = [f64::NAN; 6];
        for (k, qk) in q.iter_mut().enumerate() {
            let key = format!("J{}=", k + 1);
            let v = between(body, &key, "deg").ok_or(format!("P[{n}]: no {key}"))?;
            *qk = number(v, &format!("P[{n}] {key}"))?;
        }
        points.insert(n, q);
    }
    let mut moves = Vec::new();
    let mut messages: Vec<String> = Vec::new();
    let body = main.split_once("/MN").map_or("", |(_, b)| b);
    for (i, raw) in body.lines().enumerate() {
        let line = raw.split_once(':').map_or("", |(_, l)| l).trim();
        let at = format!("/MN line {}", i + 1);
        if line.is_empty() || line.starts_with('!') {
            continue;
        }
        if let Some(rest) = line.strip_prefix("MESSAGE[") {
            let m = rest
                .rsplit_once(']')
                .ok_or(format!("{at}: MESSAGE without ']'"))?
                .0;
            messages.push(m.to_owned());
            continue;
        }
        let above = std::mem::take(&mut messages);
        if line.trim_end_matches(';').trim() == "PAUSE" {
            stop(&mut moves, &above, i + 1)?;
        } else if let Some(rest) = line.strip_prefix("J P[") {
            let n: usize = rest
                .split(']')
                .next()
                .and_then(|n| n.trim().parse().ok())
                .ok_or(format!("{at}: bad point number"))?;
            let q = points
                .get(&n)
                .ok_or(format!("{at}: P[{n}] is not in /POS"))?;
            moves.push(ReadMove {
                joints_deg: *q,
                dwell_s: None,
                stop: None,
            });
        } else if let Some(rest) = line.strip_prefix("WAIT") {
            let t = rest.split("(sec)").next().unwrap_or("");
            dwell(&mut moves, number(t, &at)?, i + 1)?;
        }
    }
    Ok(moves)
}

/// INFORM: `Cnnnnn=p1,…,p6` pulses, `MOVJ Cnnnnn …`, `TIMER T=t` and `PAUSE`, whose
/// message is the `MSG "…"` lines right above it; degrees are pulses /
/// `pulses_per_deg`.
///
/// # Errors
/// A malformed line, a move to an undefined position.
pub fn inform(text: &str, pulses_per_deg: &[f64; 6]) -> Result<Vec<ReadMove>, String> {
    let mut points: HashMap<String, [f64; 6]> = HashMap::new();
    let mut moves = Vec::new();
    let mut messages: Vec<String> = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim_end_matches('\r').trim();
        let at = format!("line {}", i + 1);
        if line.starts_with('\'') {
            continue;
        }
        if let Some(rest) = line.strip_prefix("MSG ") {
            let m = between(rest, "\"", "\"").ok_or(format!("{at}: MSG without a string"))?;
            messages.push(m.to_owned());
            continue;
        }
        let above = std::mem::take(&mut messages);
        if line == "PAUSE" {
            stop(&mut moves, &above, i + 1)?;
        } else if line.starts_with('C') && line.contains('=') && !line.starts_with("//") {
            let (name, v) = line.split_once('=').ok_or(format!("{at}: no '='"))?;
            let p: Vec<f64> = v
                .split(',')
                .map(|x| {
                    x.trim()
                        .parse::<i64>()
                        .map(|p| p as f64)
                        .map_err(|_| format!("{at}: '{x}' is not a pulse count"))
                })
                .collect::<Result<_, _>>()?;
            let p = six(&p, &at)?;
            points.insert(
                name.to_owned(),
                core::array::from_fn(|k| p[k] / pulses_per_deg[k]),
            );
        } else if let Some(rest) = line.strip_prefix("MOVJ ") {
            let name = rest.split_whitespace().next().unwrap_or("");
            let q = points
                .get(name)
                .ok_or(format!("{at}: {name} is not defined"))?;
            moves.push(ReadMove {
                joints_deg: *q,
                dwell_s: None,
                stop: None,
            });
        } else if let Some(rest) = line.strip_prefix("TIMER T=") {
            dwell(&mut moves, number(rest, &at)?, i + 1)?;
        }
    }
    Ok(moves)
}

/// VAL3: the `jointRx` array `jZc` of the `.dtx` (`<Value key="k" j1="…" …/>`) and
/// `movej(jZc[k],…)` / `delay(t)` / `popUpMsg("…")` in `start.pgx`.
///
/// # Errors
/// A malformed value or call, a key the data does not hold.
pub fn val3(dtx: &str, start: &str) -> Result<Vec<ReadMove>, String> {
    let data = between(dtx, "<Data name=\"jZc\"", "</Data>").ok_or("no jZc data")?;
    let mut values: HashMap<usize, [f64; 6]> = HashMap::new();
    for v in data.split("<Value").skip(1) {
        let attr = |name: &str| {
            between(v, &format!(" {name}=\""), "\"").ok_or(format!("a value without {name}"))
        };
        let key: usize = attr("key")?
            .parse()
            .map_err(|_| "a key that is not a number".to_owned())?;
        let mut q = [0.0; 6];
        for (k, qk) in q.iter_mut().enumerate() {
            *qk = number(attr(&format!("j{}", k + 1))?, &format!("key {key}"))?;
        }
        values.insert(key, q);
    }
    let mut moves = Vec::new();
    for (i, raw) in start.lines().enumerate() {
        let line = raw.split("//").next().unwrap_or("").trim();
        let at = format!("start.pgx line {}", i + 1);
        if line.contains("movej(") {
            let k: usize = between(line, "jZc[", "]")
                .and_then(|k| k.trim().parse().ok())
                .ok_or(format!("{at}: not movej(jZc[k],…)"))?;
            let q = values
                .get(&k)
                .ok_or(format!("{at}: jZc[{k}] is not in the data"))?;
            moves.push(ReadMove {
                joints_deg: *q,
                dwell_s: None,
                stop: None,
            });
        } else if let Some(m) = between(line, "popUpMsg(\"", "\")") {
            stop(&mut moves, &[m.to_owned()], i + 1)?;
        } else if let Some(t) = between(line, "delay(", ")") {
            dwell(&mut moves, number(t, &at)?, i + 1)?;
        }
    }
    Ok(moves)
}

/// URScript: `movej([q1, …, q6], …)` in radians, `sleep(t)` and `popup("…", …)` (`#`
/// starts a comment).
///
/// # Errors
/// A malformed call, naming the line.
pub fn urscript(text: &str) -> Result<Vec<ReadMove>, String> {
    let mut moves = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        let at = format!("line {}", i + 1);
        if let Some(list) = line
            .strip_prefix("movej([")
            .and_then(|r| r.split(']').next())
        {
            let v: Vec<f64> = list
                .split(',')
                .map(|x| number(x, &at).map(f64::to_degrees))
                .collect::<Result<_, _>>()?;
            moves.push(ReadMove {
                joints_deg: six(&v, &at)?,
                dwell_s: None,
                stop: None,
            });
        } else if let Some(m) = line
            .strip_prefix("popup(\"")
            .and_then(|r| r.split('"').next())
        {
            stop(&mut moves, &[m.to_owned()], i + 1)?;
        } else if let Some(t) = line
            .strip_prefix("sleep(")
            .and_then(|r| r.strip_suffix(')'))
        {
            dwell(&mut moves, number(t, &at)?, i + 1)?;
        }
    }
    Ok(moves)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quoted public examples of docs/controllers/ read as their syntax says.
    #[test]
    fn readers_take_the_docs_examples() {
        let k = krl("PTP {AXIS: A1 0.00000,A2 -90.00000,A3 0.00000,A4 0.00000,A5 0.00000,A6 0.00000}\nWAIT SEC 5.000\n")
            .unwrap_or_default();
        assert_eq!(k.len(), 1);
        assert_eq!(k[0].joints_deg[1], -90.0);
        assert_eq!(k[0].dwell_s, Some(5.0));
        let r = rapid("CONST jointtarget zc_p1:=[[0,0,-70,30,-40,10],[9E9,9E9,9E9,9E9,9E9,9E9]];\nMoveAbsJ zc_p1,v200,fine,tool0;\nWaitTime 5.000;\n")
            .unwrap_or_default();
        assert_eq!(r[0].joints_deg, [0.0, 0.0, -70.0, 30.0, -40.0, 10.0]);
        let u = urscript("  movej([0.000000, -1.570796, 0.349066, -1.047198, 0.523599, 0.174533], a=0.5, v=0.2, t=0, r=0)\n  sleep(5.000)\n")
            .unwrap_or_default();
        assert!((u[0].joints_deg[1] + 90.0).abs() < 1e-4);
        assert!(krl("WAIT SEC 1\n").is_err());
        assert!(rapid("MoveAbsJ nowhere,v100,fine,tool0;\n").is_err());
    }
}
