#!/usr/bin/env python3
"""Make the lab's two fonts: egui's default Ubuntu Light and Hack, cut down
to the characters the lab draws. Run it again after lessons or widgets use
new symbols (the lesson-rendering test fails on a missing glyph).

    pip install fonttools && python3 crates/formula/fonts/subset.py

It reads the originals from egui's `epaint_default_fonts` crate in cargo's
registry and writes `kinolab-sans.ttf` and `kinolab-mono.ttf` here, renamed
as their licences ask (Ubuntu Font Licence 1.0: "… derivative Kinolab";
Hack: MIT and the Bitstream Vera licence, no "Bitstream" or "Vera" names).
"""
import glob
import os
import re

from fontTools import subset
from fontTools.ttLib import TTFont

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))

# Whole blocks a learner's text or a formula may use.
BLOCKS = [
    (0x0020, 0x007E),  # Basic Latin
    (0x00A0, 0x017F),  # Latin-1 Supplement, Latin Extended-A
    (0x0370, 0x03FF),  # Greek
    (0x2000, 0x206F),  # General Punctuation (thin spaces, dashes, primes)
    (0x2070, 0x209F),  # Superscripts and Subscripts
    (0x2100, 0x214F),  # Letterlike Symbols
    (0x2150, 0x218F),  # Number Forms
    (0x2190, 0x21FF),  # Arrows
    (0x2200, 0x22FF),  # Mathematical Operators
    (0x2300, 0x23FF),  # Miscellaneous Technical (floor, ceiling)
    (0x25A0, 0x25FF),  # Geometric Shapes (the lesson list's ● and ○)
]


def used_characters():
    """Every character in the lessons and in the Rust sources."""
    chars = set()
    files = glob.glob(os.path.join(ROOT, "lessons", "**", "*.md"), recursive=True)
    files += glob.glob(os.path.join(ROOT, "crates", "**", "*.rs"), recursive=True)
    for path in files:
        with open(path, encoding="utf-8") as f:
            chars.update(ord(c) for c in f.read())
    return chars


def original(name):
    found = sorted(glob.glob(os.path.expanduser(
        f"~/.cargo/registry/src/*/epaint_default_fonts-*/fonts/{name}")))
    if not found:
        raise SystemExit(f"{name} not found: build the lab once so cargo fetches egui")
    return found[-1]


def rename(font, family, full):
    for record in font["name"].names:
        if record.nameID in (1, 16):
            record.string = family
        elif record.nameID in (3, 4, 6):
            record.string = full if record.nameID != 6 else re.sub(r"\s+", "-", full)


def make(source, target, family, full, codepoints):
    options = subset.Options()
    options.hinting = False
    options.desubroutinize = True
    options.name_IDs = ["*"]
    options.notdef_outline = True
    font = TTFont(original(source))
    available = set(font.getBestCmap())
    subsetter = subset.Subsetter(options)
    subsetter.populate(unicodes=sorted(codepoints & available))
    subsetter.subset(font)
    rename(font, family, full)
    path = os.path.join(HERE, target)
    font.save(path)
    print(f"{target}: {len(codepoints & available)} characters, {os.path.getsize(path)} bytes")


def main():
    wanted = used_characters()
    for lo, hi in BLOCKS:
        wanted.update(range(lo, hi + 1))
    wanted = {c for c in wanted if c >= 0x20}
    make("Ubuntu-Light.ttf", "kinolab-sans.ttf", "Ubuntu Light derivative Kinolab",
         "Ubuntu Light derivative Kinolab", wanted)
    make("Hack-Regular.ttf", "kinolab-mono.ttf", "Hack derivative Kinolab",
         "Hack derivative Kinolab Regular", wanted)


if __name__ == "__main__":
    main()
