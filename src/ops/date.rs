//! DATE: the current date and time (UTC), a clock in seconds to time a
//! computation by difference ('EPOCH', as the DYNAMIC procedure does), and
//! a number of seconds written as days, hours, minutes and seconds.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;
use std::time::{SystemTime, UNIX_EPOCH};

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "DATE",
    signature: "DATE ('LETTRE') ('ANNEE'|'MOIS'|'JOUR'|'HEURE'|'MINUTE'|'SECONDE') | DATE 'EPOCH' | DATE 'CONVERSION' FLOTTANT",
    doc: "The current date (UTC) as text `dd/mm/yyyy - hh:mm:ss` (with 'LETTRE': `d month yyyy - hhHmmmin`), or one of its parts as an ENTIER (the month's name with 'LETTRE' 'MOIS'); 'EPOCH': seconds since a fixed origin, to measure a time by difference; 'CONVERSION' s: the seconds s as days, hours, minutes and seconds.",
    example: "t0 = date 'EPOCH' ; d = date ; s = date 'CONVERSION' 3725.5 ;",
    f: date,
}];

const MONTHS: [&str; 12] = [
    "janvier",
    "fevrier",
    "mars",
    "avril",
    "mai",
    "juin",
    "juillet",
    "aout",
    "septembre",
    "octobre",
    "novembre",
    "decembre",
];

fn date(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let letters = a.keyword(&["LETTRE"]).is_some();
    let now = SystemTime::now().duration_since(UNIX_EPOCH).map(|d| d.as_secs_f64()).unwrap_or(0.0);
    let part = a.keyword(&["EPOCH", "CONVERSION", "ANNEE", "MOIS", "JOUR", "HEURE", "MINUTE", "SECONDE"]);
    let (y, mo, d, h, mi, s) = civil(now);
    Ok(vec![match part {
        Some("EPOCH") => Value::Float(now),
        Some("CONVERSION") => {
            let t = a.req::<f64>()?;
            if !t.is_finite() || t < 0.0 {
                return Err(a.err(format!("the number of seconds must be finite and >= 0, found {}", t)));
            }
            let days = (t / 86400.0).floor();
            let rest = t - days * 86400.0;
            let hours = (rest / 3600.0).floor();
            let mins = ((rest - hours * 3600.0) / 60.0).floor();
            let secs = rest - hours * 3600.0 - mins * 60.0;
            Value::mot(format!("{:>9}J {:02}H {:02}min {:6.3}sec", days, hours, mins, secs))
        }
        Some("MOIS") if letters => Value::mot(MONTHS[(mo - 1) as usize]),
        Some("ANNEE") => Value::Int(y),
        Some("MOIS") => Value::Int(mo),
        Some("JOUR") => Value::Int(d),
        Some("HEURE") => Value::Int(h),
        Some("MINUTE") => Value::Int(mi),
        Some(_) => Value::Int(s),
        None if letters => Value::mot(format!("{} {} {} - {:02}H{:02}min", d, MONTHS[(mo - 1) as usize], y, h, mi)),
        None => Value::mot(format!("{:02}/{:02}/{} - {:02}:{:02}:{:02}", d, mo, y, h, mi, s)),
    }])
}

/// Year, month, day, hour, minute, second (UTC) of a time in seconds since
/// 1970-01-01, by the days-to-civil conversion of the proleptic Gregorian
/// calendar (eras of 400 years).
fn civil(t: f64) -> (i64, i64, i64, i64, i64, i64) {
    let secs = t.floor() as i64;
    let (days, sod) = (secs.div_euclid(86400), secs.rem_euclid(86400));
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d, sod / 3600, sod % 3600 / 60, sod % 60)
}

#[cfg(test)]
mod tests {
    #[test]
    fn civil_dates() {
        assert_eq!(super::civil(0.0), (1970, 1, 1, 0, 0, 0));
        // 2015-05-11 17:52:38 UTC.
        assert_eq!(super::civil(1_431_366_758.0), (2015, 5, 11, 17, 52, 38));
        // 2000-02-29 (a leap day of a century divisible by 400).
        assert_eq!(super::civil(951_782_400.0), (2000, 2, 29, 0, 0, 0));
    }
}
