// zerocal flange bracket: holds the pendant standing on the flange's side, its x along
// joint 6's axis and its z across it (the profiles' [stage2] mount_z = "x",
// mount_x = "z"; docs/mounting.md).
//
// Frame: the robot's flange frame: z along joint 6, out of the flange; the origin on
// the flange face. The bracket's underside (z = 0) is its seating face on the flange.
//
// Per-robot values: `zerocal bracket --robot R --out R.scad` writes a file that
// includes this one and sets the four interface values below from the profile's
// [flange] (ISO 9409-1 designation, dowel hole, their source). Render that file with
// OPENSCADPATH=<zerocal>/cad. This file alone renders the example values below.
//
// Tolerances (our design requirements, not robot facts): docs/mounting.md, "Design
// tolerances". T1 seat repeatability about joint 6 <= 0.0015 deg; T2 the seating face
// ground flat to 0.005 mm; T3 the dowel pressed into the bracket (H7/p6) and the
// bracket turned against the flange's dowel before the screws are tightened; T4-T6 the
// pendant seat (pendant_seat.scad). All lengths in mm.

include <pendant_seat.scad>

/* [Flange interface: ISO 9409-1, written by `zerocal bracket`] */
// Pitch circle diameter of the flange's threaded holes. Example: ISO 9409-1-50-4-M6.
pitch_circle_mm = 50;
// How many threaded holes on it.
bolt_holes = 4;
// Their metric thread's nominal diameter (6 for M6).
thread_mm = 6;
// The flange's dowel hole diameter; 0 when no source gives it.
dowel_hole_mm = 6;

/* [Bracket] */
// Where the dowel sits on the pitch circle: ISO 9409-1 puts it between two threaded
// holes; check against the robot's own flange before drilling.
dowel_angle_deg = 0;
// How far the dowel stands into the flange.
dowel_engage_mm = 5;
// Base plate thickness.
base_mm = 8;
// The seat plate's thickness (the wall the pendant stands on).
seat_plate_mm = 6;
// The ribs behind the seat plate: their length on the base, height up the plate and
// thickness.
rib_length_mm = 24;
rib_height_mm = 60;
rib_mm = 6;
// Relief in the middle of the underside: the bracket bears on an annulus around the
// bolt circle only, clear of any centring spigot of the flange.
relief_fraction = 0.6;
relief_depth_mm = 0.5;
// Show the flange (a stand-in disc) and joint 6's axis.
show_flange = true;
// Show the pendant box, see-through.
show_pendant = true;

// Screw clearance (ISO 273 medium series is about 1.1 d) and the socket head's
// counterbore (ISO 4762 heads are at most about 1.7 d across).
function clearance_mm() = 1.1 * thread_mm;
function counterbore_mm() = 1.8 * thread_mm;
function bolt_radius_mm() = pitch_circle_mm / 2;
// The base disc: the bolt circle with room for the counterbores.
function base_d_mm() = pitch_circle_mm + 2 * counterbore_mm();
// The seat plate stands behind the bolt circle (towards -x), clear of every counterbore,
// so each screw can be reached.
function seat_back_x_mm() = -(bolt_radius_mm() + counterbore_mm() / 2 + 2) - seat_plate_mm;
function seat_face_x_mm() = seat_back_x_mm() + seat_plate_mm;

module base() {
    color(bracket_colour) difference() {
        union() {
            cylinder(d = base_d_mm(), h = base_mm, $fn = 96);
            // The tab under the seat plate and its ribs.
            translate([seat_back_x_mm() - rib_length_mm, -seat_y_mm() / 2 - clamp_ear_mm, 0])
                cube([rib_length_mm - seat_back_x_mm(), seat_y_mm() + 2 * clamp_ear_mm, base_mm]);
        }
        // Screw holes, counterbored from the top, half a pitch from the dowel.
        for (k = [0 : bolt_holes - 1]) {
            a = dowel_angle_deg + 180 / bolt_holes + k * 360 / bolt_holes;
            translate([bolt_radius_mm() * cos(a), bolt_radius_mm() * sin(a), -1]) {
                cylinder(d = clearance_mm(), h = base_mm + 2, $fn = 32);
                translate([0, 0, base_mm - 0.6 * thread_mm + 1])
                    cylinder(d = counterbore_mm(), h = thread_mm, $fn = 32);
            }
        }
        // The dowel's hole in the bracket (the pin is pressed in, T3).
        if (dowel_hole_mm > 0)
            translate([bolt_radius_mm() * cos(dowel_angle_deg), bolt_radius_mm() * sin(dowel_angle_deg), -1])
                cylinder(d = dowel_hole_mm, h = base_mm + 2, $fn = 32);
        // The relief: the seating face is the annulus outside it (T2).
        translate([0, 0, -1])
            cylinder(d = relief_fraction * pitch_circle_mm, h = relief_depth_mm + 1, $fn = 64);
    }
    if (dowel_hole_mm > 0)
        color("dimgray")
            translate([bolt_radius_mm() * cos(dowel_angle_deg), bolt_radius_mm() * sin(dowel_angle_deg), -dowel_engage_mm])
                cylinder(d = dowel_hole_mm, h = base_mm + dowel_engage_mm, $fn = 32);
    else
        echo("WARNING: no dowel: the bracket's turn about joint 6 is held by the screws' clamp alone; fit a dowel to the flange's own hole (docs/mounting.md, T3)");
}

// The pendant seat, turned so that the pendant's x runs along joint 6 (flange z) and its
// z along the flange's x; its y is then the flange's -y.
module seat() {
    multmatrix([
        [0, 0, 1, seat_face_x_mm()],
        [0, -1, 0, box_y_mm / 2],
        [1, 0, 0, base_mm + rim_clearance_mm + rim_wall_mm],
        [0, 0, 0, 1],
    ]) {
        pendant_seat(plate_mm = seat_plate_mm);
        if (show_pendant) pendant_box_ghost();
    }
    // Two ribs behind the seat plate: the pendant's weight must not bend it (T7).
    color(bracket_colour) for (y = [-seat_y_mm() / 4, seat_y_mm() / 4])
        translate([0, y + rib_mm / 2, base_mm])
            rotate([90, 0, 0])
                linear_extrude(height = rib_mm)
                    polygon([
                        [seat_back_x_mm() - rib_length_mm, 0],
                        [seat_back_x_mm(), 0],
                        [seat_back_x_mm(), rib_height_mm],
                    ]);
}

module flange_bracket() {
    base();
    seat();
    if (show_flange) {
        // The flange (a stand-in disc) and joint 6's axis.
        color([0.5, 0.5, 0.5, 0.35])
            translate([0, 0, -12]) cylinder(d = pitch_circle_mm + 2 * counterbore_mm(), h = 12, $fn = 96);
        color("royalblue") translate([0, 0, -30]) cylinder(d = 1.2, h = base_mm + box_x_mm + 50, $fn = 12);
    }
}

flange_bracket();
