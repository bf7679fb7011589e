// Flange bracket for the Bracket test fixture (the paper's wrist with a made-up flange), from the [flange] of profile 'bracket-fixture'.
// Written by `zerocal bracket`: edit the profile, not this file.
// Interface: ISO 9409-1-31.5-4-M5 (T: made up for the bracket golden test: not any robot's flange)
// Registers on: the made-up flange's face and its 5 mm dowel hole (T)
// Tolerances: docs/mounting.md, "Design tolerances". Render with OPENSCADPATH=<zerocal>/cad.
include <flange_bracket.scad>
pitch_circle_mm = 31.5;
bolt_holes = 4;
thread_mm = 5;
dowel_hole_mm = 5;
