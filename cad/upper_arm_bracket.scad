// zerocal upper-arm bracket: a saddle strapped to the upper arm (link 2) that holds the
// pendant level at the stage-1 pose, its x along joint 2's axis and its z up (the
// profiles' [stage1]; docs/mounting.md).
//
// Frame: the stage-1 pose: z up along the upper arm, x along joint 2's axis, y out of
// the arm's face the saddle sits on. The arm's section is a parameter (a rectangle or
// a circle); no public source names a machined reference on link 2 of the built-in
// robots (their [stage1] registers_on), so the saddle registers on the cast surface by
// three pads and a reference lip, and its seat is calibrated on the bracket (the
// reversal on a surface plate) rather than taken from the robot.
//
// Tolerances (our design requirements, not robot facts): docs/mounting.md, "Design
// tolerances". T1 seat repeatability about joint 2 <= 0.0015 deg; T8 the three pads
// spread at least 100 mm along the arm, the reference lip ground straight; T4-T6 the
// pendant seat (pendant_seat.scad). All lengths in mm.

include <pendant_seat.scad>

/* [The arm's section at the bracket: measure it on the robot] */
// "rect" or "round".
arm_section = "rect";
// Rectangular section: across (along joint 2's axis) and deep (along y). Example values.
arm_width_mm = 120;
arm_depth_mm = 100;
// Round section: its diameter. Example value.
arm_round_d_mm = 110;

/* [Saddle] */
// The pendant's clamp strap runs along x: its ears stand at the box's ends, clear of
// the arm.
clamp_across = "x";
// Along the arm: the pads' spread along it sets how much a speck under a pad turns the
// bracket about joint 2 (T8).
saddle_length_mm = 130;
saddle_thickness_mm = 14;
// The pads the saddle bears on: diameter and height off the saddle's back.
pad_d_mm = 10;
pad_height_mm = 1.5;
pad_inset_mm = 10;
// The reference lip along the saddle's +x edge (rectangular section): it butts against
// the arm's side face and keeps the pendant's x along joint 2.
reference_lip = true;
lip_mm = 6;
// Strap slots across the saddle for the two straps around the arm.
strap_width_mm = 20;
strap_thickness_mm = 2;
// The shelf under the pendant seat.
shelf_mm = 8;
// Show the arm and the pendant, see-through.
show_arm = true;
show_pendant = true;

function saddle_width_mm() = seat_x_mm();
// The three pads on the saddle's back (x, z): two low across the arm, one high. For a
// round section they stand on the V's flanks instead (see pads()).
function pad_points() = [
    [-saddle_width_mm() / 2 + pad_inset_mm + pad_d_mm / 2, pad_inset_mm + pad_d_mm / 2],
    [saddle_width_mm() / 2 - pad_inset_mm - pad_d_mm / 2, pad_inset_mm + pad_d_mm / 2],
    [0, saddle_length_mm - pad_inset_mm - pad_d_mm / 2],
];
function pad_spread_along_arm_mm() = pad_points()[2][1] - pad_points()[0][1];

// The V for a round section: 90 degrees, cut into the saddle's back. A circle of
// radius R touches a 90-degree V's flank R from its apex; the V is made 1.3 times that
// deep so each pad stands inside its flank. The saddle thickens to hold it.
function round_r_mm() = arm_round_d_mm / 2 + pad_height_mm;
function v_depth_mm() = 1.3 * round_r_mm() / sqrt(2);
function saddle_t_mm() = arm_section == "round" ? max(saddle_thickness_mm, v_depth_mm() + 8) : saddle_thickness_mm;
// The arm's front (largest y): the shelf and the pendant stand clear of it, the arm
// going on up past the saddle.
function round_centre_y_mm() = pad_height_mm + v_depth_mm() - round_r_mm() * sqrt(2);
function arm_front_y_mm() = arm_section == "round" ? round_centre_y_mm() + arm_round_d_mm / 2 : 0;
// Where the seat plate starts (y).
function shelf_y0_mm() = max(pad_height_mm, arm_front_y_mm() + 2);
// Where the circle touches a flank (x, y), side -1 or 1.
function v_contact(side) = [side * round_r_mm() / sqrt(2), pad_height_mm + v_depth_mm() - round_r_mm() / sqrt(2)];

module saddle() {
    color(bracket_colour) difference() {
        union() {
            translate([-saddle_width_mm() / 2, pad_height_mm, 0])
                cube([saddle_width_mm(), saddle_t_mm(), saddle_length_mm]);
            if (arm_section == "rect") {
                // The pads, ground coplanar.
                for (p = pad_points())
                    translate([p[0], pad_height_mm, p[1]]) rotate([90, 0, 0])
                        cylinder(d = pad_d_mm, h = pad_height_mm, $fn = 40);
                // The reference lip against the arm's side face.
                if (reference_lip) {
                    // Its ground inner face at x = arm_width_mm / 2, reaching lip_mm down
                    // the side face; a web joins it to the saddle when the arm is wider.
                    translate([arm_width_mm / 2, -lip_mm, 0])
                        cube([lip_mm, lip_mm + pad_height_mm + saddle_t_mm(), saddle_length_mm]);
                    if (arm_width_mm / 2 > saddle_width_mm() / 2)
                        translate([saddle_width_mm() / 2 - 1, pad_height_mm, 0])
                            cube([arm_width_mm / 2 - saddle_width_mm() / 2 + 1, saddle_t_mm(), saddle_length_mm]);
                }
            }
        }
        if (arm_section == "round")
            // The V along the arm.
            translate([0, pad_height_mm, -1]) linear_extrude(height = saddle_length_mm + 2)
                polygon([[-v_depth_mm(), -0.01], [v_depth_mm(), -0.01], [0, v_depth_mm()]]);
        // Strap slots at the pads' heights.
        for (z = [pad_points()[0][1], pad_points()[2][1]])
            translate([-saddle_width_mm() / 2 - 1, pad_height_mm + saddle_t_mm() - strap_thickness_mm - 3, z - strap_width_mm / 2])
                cube([saddle_width_mm() + 2, strap_thickness_mm + 1, strap_width_mm]);
    }
    if (arm_section == "round")
        // Three pads on the V's flanks: two along one flank (they set the turn about
        // joint 2), one on the other.
        color(bracket_colour)
            for (p = [[-1, pad_points()[0][1]], [-1, pad_points()[2][1]], [1, saddle_length_mm / 2]])
                // On the flank, pointing into the V at the contact point.
                translate([v_contact(p[0])[0] + p[0] * pad_height_mm / sqrt(2), v_contact(p[0])[1] + pad_height_mm / sqrt(2), p[1]])
                    rotate([0, 0, -p[0] * 45]) rotate([90, 0, 0])
                        cylinder(d = pad_d_mm, h = pad_height_mm, $fn = 40);
}

// The shelf on top of the saddle and the pendant seat on it: the pendant's x along x
// (joint 2), its z up.
module shelf() {
    y0 = shelf_y0_mm() + rim_clearance_mm + rim_wall_mm;
    translate([-box_x_mm / 2, y0, saddle_length_mm + shelf_mm]) {
        pendant_seat(plate_mm = shelf_mm);
        if (show_pendant) pendant_box_ghost();
    }
    // Two ribs under the shelf's overhang.
    color(bracket_colour)
        for (x = [-saddle_width_mm() / 4, saddle_width_mm() / 4])
            translate([x - 3, 0, 0]) rotate([90, 0, 90]) linear_extrude(height = 6)
                polygon([
                    [pad_height_mm + saddle_t_mm(), saddle_length_mm],
                    [shelf_y0_mm() + seat_y_mm() - 2, saddle_length_mm],
                    [pad_height_mm + saddle_t_mm(), saddle_length_mm - seat_y_mm() * 0.8],
                ]);
}

module arm_ghost() {
    color([0.5, 0.5, 0.5, 0.3]) translate([0, 0, -60])
        if (arm_section == "rect")
            translate([-arm_width_mm / 2, -arm_depth_mm, 0]) cube([arm_width_mm, arm_depth_mm, saddle_length_mm + 120]);
        else
            translate([0, round_centre_y_mm(), 0])
                cylinder(d = arm_round_d_mm, h = saddle_length_mm + 120, $fn = 96);
    // Joint 2's axis direction, drawn along x through the seat.
    color("royalblue") translate([-saddle_width_mm(), shelf_y0_mm() + seat_y_mm() / 2, saddle_length_mm + shelf_mm + box_z_mm / 2])
        rotate([0, 90, 0]) cylinder(d = 1.2, h = 2 * saddle_width_mm(), $fn = 12);
}

module upper_arm_bracket() {
    saddle();
    shelf();
    if (show_arm) arm_ghost();
}

upper_arm_bracket();
