//! pest pairs -> AST. One function per rule family; spans are converted to
//! our own byte spans at every node, so no pest type escapes this module.
//! pest sees one instruction at a time: `base` is where that instruction
//! starts in the whole text, added to every span.

use super::ast::*;
use super::parser::Rule;
use crate::error::{Error, Result};
use crate::source::Span;
use pest::iterators::Pair;

fn span_of(p: &Pair<Rule>, base: usize) -> Span {
    let s = p.as_span();
    Span::new(base + s.start(), base + s.end())
}

/// Lower one `instruction` pair.
pub fn instruction(p: Pair<Rule>, base: usize) -> Result<Instr> {
    let span = span_of(&p, base);
    let mut targets = Vec::new();
    let mut items = Vec::new();
    for c in p.into_inner() {
        match c.as_rule() {
            Rule::assign => {
                for t in c.into_inner() {
                    if t.as_rule() == Rule::target {
                        targets.push(target(t, base)?);
                    }
                }
            }
            Rule::semicolon => {}
            _ => push_item(&mut items, c, base)?,
        }
    }
    Ok(Instr { targets, items, span })
}

fn target(p: Pair<Rule>, base_offset: usize) -> Result<Target> {
    let span = span_of(&p, base_offset);
    let mut name = String::new();
    let mut typed = None;
    let mut keys = Vec::new();
    let mut base = None;
    for c in p.into_inner() {
        match c.as_rule() {
            Rule::name if name.is_empty() && base.is_none() => name = c.as_str().to_uppercase(),
            Rule::counter if name.is_empty() && base.is_none() => name = c.as_str().to_uppercase(),
            Rule::member if name.is_empty() && base.is_none() => name = c.as_str().to_uppercase(),
            Rule::group if name.is_empty() && base.is_none() => {
                let mut items = Vec::new();
                push_item(&mut items, c, base_offset)?;
                if let Some(Item { kind: ItemKind::Group(g), .. }) = items.pop() {
                    base = Some(g);
                }
            }
            // `x*'FLOTTANT' = …`: the type may be quoted.
            Rule::typed => {
                let n = c.into_inner().next().map(|n| match n.as_rule() {
                    Rule::string => n.into_inner().next().map_or("", |i| i.as_str()).to_uppercase(),
                    _ => n.as_str().to_uppercase(),
                });
                typed = n;
            }
            Rule::dot => {}
            _ => push_item(&mut keys, c, base_offset)?,
        }
    }
    Ok(Target { name, base, typed, keys, span })
}

/// Is this item a value that a following glued `-1` or `.1` attaches to?
fn value_like(it: &Item) -> bool {
    matches!(
        it.kind,
        ItemKind::Int(_)
            | ItemKind::Float(_)
            | ItemKind::Str(_)
            | ItemKind::Word(_)
            | ItemKind::Counter(_)
            | ItemKind::Group(_)
    )
}

fn glued_to_previous(items: &[Item], span: Span) -> bool {
    items.last().is_some_and(|prev| prev.span.end == span.start && value_like(prev))
}

fn push_item(items: &mut Vec<Item>, p: Pair<Rule>, base: usize) -> Result<()> {
    let span = span_of(&p, base);
    let kind = match p.as_rule() {
        Rule::number => {
            let text = p.as_str();
            // `T.1` is indexing, not the number .1: a leading dot glued to a
            // value is the `.` separator (language.md §1).
            if text.starts_with('.') && glued_to_previous(items, span) {
                items.push(Item { kind: ItemKind::Dot, span: Span::new(span.start as usize, span.start as usize + 1) });
                let rest = Span::new(span.start as usize + 1, span.end as usize);
                items.push(Item { kind: number(&text[1..], rest)?, span: rest });
                return Ok(());
            }
            number(text, span)?
        }
        Rule::signed_number => {
            let text = p.as_str();
            // The sign rule: `A-1` subtracts, `A -1` is two operands,
            // `CRIT*-1` multiplies by -1.
            if glued_to_previous(items, span) {
                let sym = if text.starts_with('-') { "-" } else { "+" };
                items.push(Item {
                    kind: ItemKind::Sym(sym),
                    span: Span::new(span.start as usize, span.start as usize + 1),
                });
                let rest = Span::new(span.start as usize + 1, span.end as usize);
                // `A-E2` subtracts the object E2: without its sign, a bare
                // exponent is a name.
                let kind = match text[1..].starts_with(|c: char| c.is_ascii_alphabetic()) {
                    true => ItemKind::Word(text[1..].to_uppercase()),
                    false => number(&text[1..], rest)?,
                };
                items.push(Item { kind, span: rest });
                return Ok(());
            }
            match number(&text[1..], span)? {
                ItemKind::Int(i) if text.starts_with('-') => ItemKind::Int(-i),
                ItemKind::Float(f) if text.starts_with('-') => ItemKind::Float(-f),
                k => k,
            }
        }
        Rule::string => {
            let inner = p.into_inner().next().map_or("", |i| i.as_str());
            ItemKind::Str(inner.replace("''", "'"))
        }
        Rule::counter => {
            let n = p.into_inner().next().map_or(String::new(), |n| n.as_str().to_uppercase());
            ItemKind::Counter(n)
        }
        Rule::name => ItemKind::Word(p.as_str().to_uppercase()),
        Rule::symbol => ItemKind::Sym(symbol(&p.as_str().to_uppercase())),
        Rule::dot => ItemKind::Dot,
        Rule::group => {
            let mut inner = Vec::new();
            for c in p.into_inner() {
                if c.as_rule() != Rule::close {
                    push_item(&mut inner, c, base)?;
                }
            }
            ItemKind::Group(inner)
        }
        r => return Err(Error::syntax(format!("unexpected {:?}", r), span)),
    };
    items.push(Item { kind, span });
    Ok(())
}

fn symbol(s: &str) -> &'static str {
    match s {
        "**" => "**",
        "*" => "*",
        "/" => "/",
        "+" => "+",
        "-" => "-",
        "<EG" => "<EG",
        ">EG" => ">EG",
        "<" => "<",
        ">" => ">",
        _ => "%",
    }
}

/// Cast3M's number rule (redlec.eso): no `.` and no exponent is an ENTIER
/// when it has at most 9 digits (every digit counts, leading zeros too);
/// more digits make it a FLOTTANT, as do a `.` or an exponent. `D` and `Q`
/// exponents are Fortran spellings of `E`. A literal beyond the range of a
/// FLOTTANT (`1.E999`) is refused here: it would be an infinity that no
/// later check sees coming from the text.
fn number(text: &str, span: Span) -> Result<ItemKind> {
    // `E2` alone (from `-E2`): an exponent without mantissa, whose mantissa is 0.
    if text.starts_with(|c: char| c.is_ascii_alphabetic()) {
        return number(&format!("0{}", text), span);
    }
    let is_float = text.contains(['.', 'e', 'E', 'd', 'D', 'q', 'Q']);
    if !is_float && text.len() <= MAX_INT_DIGITS {
        return text
            .parse::<i64>()
            .map(ItemKind::Int)
            .map_err(|_| Error::syntax(format!("'{}' is not a number", text), span));
    }
    let norm: String = text.chars().map(|c| if matches!(c, 'd' | 'D' | 'q' | 'Q') { 'E' } else { c }).collect();
    match norm.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(ItemKind::Float(x)),
        Ok(_) => Err(Error::syntax(
            format!("the number '{}' is beyond the range of a FLOTTANT (about 1.8E+308)", clip(text)),
            span,
        )),
        Err(_) => Err(Error::syntax(format!("'{}' is not a number", clip(text)), span)),
    }
}

/// Digits an ENTIER literal may have (NFIX in redlec.eso).
const MAX_INT_DIGITS: usize = 9;

/// A literal as quoted in a message: a 100,000-digit number is shown by
/// its ends.
fn clip(text: &str) -> String {
    match text.len() {
        n if n <= 40 => text.to_string(),
        n => format!("{}…{} ({} characters)", &text[..20], &text[n - 10..], n),
    }
}
