//! Element colours (Cast3M's `COUL`): a mesh remembers the colour of its
//! elements, which pictures use. The names are Cast3M's, matched on their
//! first 4 letters like every Cast3M word; `DEFA` (the default) leaves the
//! choice to the picture.

/// A colour, as an index into [`NAMES`]; `Colour::default()` is `DEFA`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, PartialOrd, Ord)]
pub struct Colour(u8);

/// Cast3M's colour names (the eight historical ones first, in Cast3M's
/// numbering), with the RGB pictures draw them in. Pictures have a white
/// background, where Cast3M's default is black: `BLAN` is drawn light grey
/// and `JAUN` a darker yellow so that both stay visible.
const NAMES: &[(&str, [u8; 3])] = &[
    ("DEFA", [0, 0, 0]),
    ("BLEU", [0, 0, 230]),
    ("ROUG", [220, 0, 0]),
    ("ROSE", [230, 0, 200]),
    ("VERT", [0, 160, 0]),
    ("TURQ", [0, 190, 190]),
    ("JAUN", [210, 180, 0]),
    ("BLAN", [200, 200, 200]),
    ("NOIR", [0, 0, 0]),
    ("ORAN", [255, 140, 0]),
    ("VIOL", [130, 0, 200]),
    ("OCEA", [0, 90, 160]),
    ("CYAN", [0, 230, 230]),
    ("OLIV", [128, 128, 0]),
    ("GRIS", [128, 128, 128]),
    ("AZUR", [0, 127, 255]),
    // Cast3M's extended palette, drawn in the X11 colours it names.
    ("POUR", [208, 32, 144]),
    ("BRUN", [139, 69, 19]),
    ("BRIQ", [178, 34, 34]),
    ("CORA", [255, 127, 80]),
    ("BEIG", [245, 222, 179]),
    ("OR", [255, 215, 0]),
    ("MARI", [0, 0, 128]),
    ("BOUT", [0, 100, 0]),
    ("LIME", [127, 255, 0]),
    ("LAVA", [230, 230, 250]),
    ("BRON", [218, 165, 32]),
    ("KAKI", [240, 230, 140]),
    ("PEAU", [255, 182, 193]),
    ("CARA", [205, 133, 63]),
    ("INDI", [75, 0, 130]),
];

impl Colour {
    /// The colour a word names (`'ROUGE'` and `'ROUG'` alike), if any.
    pub fn from_name(word: &str) -> Option<Colour> {
        let key: String = word.trim().to_uppercase().chars().take(4).collect();
        NAMES.iter().position(|(n, _)| *n == key).map(|i| Colour(i as u8))
    }

    /// Cast3M's 4-letter name.
    pub fn name(self) -> &'static str {
        NAMES[self.0 as usize].0
    }

    /// The RGB to draw with; `None` for the default colour.
    pub fn rgb(self) -> Option<[u8; 3]> {
        (self.0 != 0).then(|| NAMES[self.0 as usize].1)
    }

    pub fn is_default(self) -> bool {
        self.0 == 0
    }

    /// Every name, for messages.
    pub fn names() -> impl Iterator<Item = &'static str> {
        NAMES.iter().map(|(n, _)| *n)
    }
}

#[cfg(test)]
mod tests {
    use super::Colour;

    #[test]
    fn names_match_on_four_letters_and_default_has_no_rgb() {
        assert_eq!(Colour::from_name("rouge").map(Colour::name), Some("ROUG"));
        assert_eq!(Colour::from_name("TURQUOISE").map(Colour::name), Some("TURQ"));
        assert_eq!(Colour::from_name("MAUVE"), None);
        assert_eq!(Colour::from_name("BRONZE").map(Colour::name), Some("BRON"));
        assert_eq!(Colour::from_name("OR").map(Colour::name), Some("OR"));
        assert_eq!(Colour::default().name(), "DEFA");
        assert!(Colour::default().rgb().is_none());
        assert_eq!(Colour::from_name("ROUG").unwrap().rgb(), Some([220, 0, 0]));
    }
}
