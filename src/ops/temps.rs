//! TEMP (temp.notice): the time spent, as a printed report or as objects.
//! gibi runs in one thread and has no CPU clock of its own: "CPU" times
//! are wall-clock times, and the efficiency (CPU over clock) is 100 %.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;
use std::time::Duration;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "TEMP",
    signature: "TEMP ('IMPR' ('SOMM'|'MAXI') ('HORL'|'CPU'|'APPE'|'EFFI')) | TEMP 'ZERO'|'PLAC'|'NOEC' | \
                TEMP 'ENTI' ('CPU'|'HORL') | TEMP 'SGAC' ('IMPR')",
    doc: "Print the time spent per operator and per solver phase ('HORL', 'CPU' sort by time, 'APPE' by calls). \
          Returns a TABLE ('NOEC': print nothing): 'TEMPS_CPU' and 'TEMPS_HORLOGE', each a TABLE with 'INITIAL' \
          (milliseconds since the start or the last 'ZERO') and 'ECOULE' (since the previous TEMP), 'APPELS' \
          (operator name -> LISTENTI of its calls) and 'EFFICACITE' (name -> LISTREEL, in %). 'ENTI': the \
          milliseconds since the start as an ENTIER. 'ZERO' restarts the counts. gibi has no CPU clock (CPU \
          times are wall-clock times) and no ESOPE segments ('PLAC' says so; 'SGAC' gives 0 segments of 0 words).",
    example: "t = temp 'NOEC' ; mess (t . 'TEMPS_HORLOGE' . 'INITIAL') ;",
    f: temp,
}];

const WORDS: &[&str] = &["ZERO", "IMPR", "SOMM", "MAXI", "HORL", "CPU", "APPE", "EFFI", "NOEC", "SGAC", "PLAC", "ENTI"];

fn temp(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut words = Vec::new();
    while let Some(w) = a.keyword(WORDS) {
        words.push(w);
    }
    let has = |w: &str| words.contains(&w);
    let now = std::time::Instant::now();
    if has("ZERO") {
        it.timers = Default::default();
        it.timers.zeroed = true;
        for op in it.registry.all() {
            op.reset_stats();
        }
        return Ok(vec![]);
    }
    if has("ENTI") {
        return Ok(vec![Value::Int(millis(now - it.timers.origin))]);
    }
    if has("PLAC") {
        it.println("TEMP 'PLAC': gibi has no ESOPE memory segments to report");
        return Ok(vec![]);
    }
    if has("SGAC") {
        if has("IMPR") {
            it.println("TEMP 'SGAC': gibi has no ESOPE segments: 0 active, 0 words");
        }
        return Ok(vec![Value::Int(0), Value::Int(0)]);
    }
    let calls = counts(it);
    if !has("NOEC") {
        report(it, &calls, has("APPE"));
    }
    // The clocks as a table, the form decks read timings from.
    let clock = |it: &Interp| {
        let mut c = Table::new();
        c.set(Key::Mot("INITIAL".into()), Value::Int(millis(now - it.timers.origin)));
        c.set(Key::Mot("ECOULE".into()), Value::Int(millis(now - it.timers.last)));
        table(c)
    };
    let mut appels = Table::new();
    let mut effi = Table::new();
    for (name, n, _) in &calls {
        appels.set(Key::Mot(name.to_string()), Value::ListEnti(Rc::new(vec![*n as i64])));
        effi.set(Key::Mot(name.to_string()), Value::ListReel(Rc::new(vec![100.0])));
    }
    let mut t = Table::new();
    t.set(Key::Mot("TEMPS_CPU".into()), clock(it));
    t.set(Key::Mot("TEMPS_HORLOGE".into()), clock(it));
    t.set(Key::Mot("APPELS".into()), table(appels));
    t.set(Key::Mot("EFFICACITE".into()), table(effi));
    it.timers.last = now;
    it.timers.zeroed = false;
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}

fn table(t: Table) -> Value {
    Value::Table(Rc::new(RefCell::new(t)))
}

fn millis(d: Duration) -> i64 {
    i64::try_from(d.as_millis()).unwrap_or(i64::MAX)
}

/// Every operator called since the start or the last 'ZERO': name, calls,
/// time. TEMP counts this call too (its record comes when it returns), but
/// not the 'ZERO' call that restarted the counts.
fn counts(it: &Interp) -> Vec<(&'static str, u64, Duration)> {
    let mut out = Vec::new();
    for op in it.registry.all() {
        let (mut n, d) = op.stats();
        if op.name == "TEMP" {
            n = (n + 1).saturating_sub(u64::from(it.timers.zeroed));
        }
        if n > 0 {
            out.push((op.name, n, d));
        }
    }
    out
}

/// One line per operator, the longest first (by calls with 'APPE'), then
/// the solver phases.
fn report(it: &mut Interp, calls: &[(&'static str, u64, Duration)], by_calls: bool) {
    let mut ops = calls.to_vec();
    if by_calls {
        ops.sort_by_key(|x| std::cmp::Reverse(x.1));
    } else {
        ops.sort_by_key(|x| std::cmp::Reverse(x.2));
    }
    let mut lines = vec![format!("{:<10} {:>8} {:>12}", "operator", "calls", "seconds")];
    for (k, n, d) in ops {
        lines.push(format!("{:<10} {:>8} {:>12.6}", k, n, d.as_secs_f64()));
    }
    if !it.timers.phases.is_empty() {
        lines.push(format!("{:<24} {:>8} {:>12}", "solver phase", "count", "seconds"));
        for (k, (n, d)) in &it.timers.phases {
            lines.push(format!("{:<24} {:>8} {:>12.6}", k, n, d.as_secs_f64()));
        }
    }
    for l in lines {
        it.println(&l);
    }
}
