// Flange bracket for the Universal Robots UR5e, from the [flange] of profile 'ur5e'.
// Written by `zerocal bracket`: edit the profile, not this file.
// Interface: ISO 9409-1-50-4-M6 (S6: graspmonkey (a gripper retailer), 'ISO 9409-1: The interface between robot and tool', https://graspmonkey.de/en/blogs/news/iso-9409-1-die-schnittstelle-zwischen-roboter-und-werkzeug: lists ISO 9409-1-50-4-M6 for the UR3e, UR5e, UR10e and UR16e (a secondary source, 'all statements without guarantee'; UR's own manual was not reached))
// Registers on: the flange's tool-mounting face and its ISO 9409-1-50-4-M6 bolt circle (S6); the dowel hole's size is not in a source reached (see missing), so the bracket's dowel is fitted to the flange's own hole
// Tolerances: docs/mounting.md, "Design tolerances". Render with OPENSCADPATH=<zerocal>/cad.
include <flange_bracket.scad>
pitch_circle_mm = 50;
bolt_holes = 4;
thread_mm = 6;
dowel_hole_mm = 0; // no source gives the flange's dowel hole: fit the bracket's dowel to the flange's own hole
