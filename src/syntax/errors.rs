//! Human names for grammar rules, so syntax errors never show rule names.
//! The match is exhaustive: a new rule without a name does not compile.

use super::parser::Rule;

pub fn rule_name(rule: &Rule) -> &'static str {
    match rule {
        Rule::EOI => "the end of the text",
        Rule::WHITESPACE => "a blank",
        Rule::program => "a program",
        Rule::instruction => "an instruction",
        Rule::semicolon => "';' to end the instruction",
        Rule::assign => "names followed by '='",
        Rule::equals => "'='",
        Rule::target => "a name to assign",
        Rule::typed => "a type after '*'",
        Rule::key => "a table key",
        Rule::item => "an operand or an operator",
        Rule::group => "a parenthesised group",
        Rule::close => "')' to close the group",
        Rule::string => "a quoted text",
        Rule::str_inner => "the text of a quote",
        Rule::counter => "a loop counter '&name'",
        Rule::member => "an object entry '%name'",
        Rule::number => "a number",
        Rule::exponent => "an exponent",
        Rule::signed_number => "a signed number",
        Rule::symbol => "an operator symbol",
        Rule::dot => "'.'",
        Rule::name => "a name",
        Rule::separator => "a separator",
    }
}
