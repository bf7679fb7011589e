// zerocal: the pendant seat both brackets share (included by flange_bracket.scad and
// upper_arm_bracket.scad). The pendant box rests on three ground lands and is located
// in their plane by a round pin and a relieved (diamond) pin.
//
// Frame of this module: the seat plane is z = 0, the box above it (+z, the pendant's
// z); the pendant's x runs along +x, the round pin at the low-x end.
//
// Tolerances (design requirements, not robot facts; docs/mounting.md, "Design
// tolerances"): T4 lands ground coplanar, T5 pins pressed H7/p6 with the box pushed
// against them before it is clamped, T6 the clamp force inside the lands' triangle.
// All lengths in mm.

/* [Pendant box: set these from the enclosure's drawing] */
// Along the pendant's x. Example value, not a drawing's.
box_x_mm = 96;
// Along the pendant's y. Example value, not a drawing's.
box_y_mm = 64;
// Along the pendant's z (its height off the seat). Example value, not a drawing's.
box_z_mm = 32;

/* [Seat] */
// Height of the lands above the seat plate: the plate itself never touches the box.
land_height_mm = 1.0;
// Diameter of each land.
land_d_mm = 8;
// Inset of the lands and pins from the box outline.
land_inset_mm = 7;
// Locating pin diameter (pressed into the seat, H7/p6; the box's holes reamed H7).
pin_d_mm = 4;
// How far the pins stand above the lands.
pin_height_mm = 4;
// Width left on the diamond pin's two locating lands (it locates across the pin line only).
diamond_land_mm = 1.2;
// Guide rim around the box: clearance to the box and height. It never locates.
rim_clearance_mm = 0.5;
rim_height_mm = 3;
rim_wall_mm = 3;
// Clamp: two tapped holes for a strap across the box, inside the lands' triangle (T6).
clamp_thread_mm = 4;
// The brackets' colour in pictures.
bracket_colour = "lightsteelblue";

// The strap crosses the box over the lands' centroid, so its force cannot tip the box
// off a land (T6); its ears stand outside the rim, either side of the box along y
// (clamp_across = "y") or at its ends along x ("x"), whichever side is free.
clamp_across = "y";
clamp_ear_mm = 12;
function lands_centroid() = (land_points()[0] + land_points()[1] + land_points()[2]) / 3;
function clamp_ears() = let (c = lands_centroid(), out = rim_clearance_mm + rim_wall_mm + clamp_ear_mm / 2)
    clamp_across == "y"
        ? [[c[0], -out], [c[0], box_y_mm + out]]
        : [[-out, c[1]], [box_x_mm + out, c[1]]];

// The seat plate's outline: the box with its rim.
function seat_x_mm() = box_x_mm + 2 * (rim_clearance_mm + rim_wall_mm);
function seat_y_mm() = box_y_mm + 2 * (rim_clearance_mm + rim_wall_mm);

// The three lands: two across the box at its low-x end, one at its high-x end. Their
// spread across y sets how far a speck under one land tilts the box about its x: the
// bracket's axis that matters (docs/mounting.md, T4).
function land_points() = [
    [land_inset_mm, land_inset_mm],
    [land_inset_mm, box_y_mm - land_inset_mm],
    [box_x_mm - land_inset_mm, box_y_mm / 2],
];

// The two pins on the box's centre line along x, between the lands.
function round_pin_point() = [land_inset_mm + land_d_mm + pin_d_mm, box_y_mm / 2];
function diamond_pin_point() = [box_x_mm - 2 * land_inset_mm - land_d_mm - pin_d_mm, box_y_mm / 2];
function pin_spacing_mm() = diamond_pin_point()[0] - round_pin_point()[0];

// The seat: lands, pins, rim and clamp holes on a plate of `plate_mm` thickness whose
// top is z = 0. The box's corner (its low x, low y) is at the origin.
module pendant_seat(plate_mm = 6) {
    color(bracket_colour) difference() {
        union() {
            // The plate.
            translate([-rim_clearance_mm - rim_wall_mm, -rim_clearance_mm - rim_wall_mm, -plate_mm])
                cube([seat_x_mm(), seat_y_mm(), plate_mm]);
            // The rim: guides the box on, never touches it once seated.
            translate([-rim_clearance_mm - rim_wall_mm, -rim_clearance_mm - rim_wall_mm, 0])
                difference() {
                    cube([seat_x_mm(), seat_y_mm(), rim_height_mm]);
                    translate([rim_wall_mm, rim_wall_mm, -1])
                        cube([box_x_mm + 2 * rim_clearance_mm, box_y_mm + 2 * rim_clearance_mm, rim_height_mm + 2]);
                }
            // Ears for the clamp strap, either side of the box.
            for (e = clamp_ears())
                translate([e[0] - clamp_ear_mm / 2, e[1] - clamp_ear_mm / 2, -plate_mm])
                    cube([clamp_ear_mm, clamp_ear_mm, plate_mm]);
            // The lands (ground coplanar, T4).
            for (p = land_points()) translate([p[0], p[1], 0])
                cylinder(d = land_d_mm, h = land_height_mm, $fn = 48);
        }
        // Clamp holes in the ears: the strap crosses the box over the lands' centroid.
        for (e = clamp_ears())
            translate([e[0], e[1], -plate_mm - 1])
                cylinder(d = clamp_thread_mm * 0.85, h = plate_mm + 2, $fn = 24);
    }
    // The pins (pressed, T5): round, and diamond relieved along the pin line.
    color("dimgray") {
        translate([round_pin_point()[0], round_pin_point()[1], -plate_mm])
            cylinder(d = pin_d_mm, h = plate_mm + land_height_mm + pin_height_mm, $fn = 32);
        translate([diamond_pin_point()[0], diamond_pin_point()[1], -plate_mm])
            intersection() {
                cylinder(d = pin_d_mm, h = plate_mm + land_height_mm + pin_height_mm, $fn = 32);
                translate([-diamond_land_mm / 2, -pin_d_mm, 0])
                    cube([diamond_land_mm, 2 * pin_d_mm, plate_mm + land_height_mm + pin_height_mm]);
            }
    }
}

// The pendant box, see-through, seated on the lands.
module pendant_box_ghost() {
    color([1.0, 0.55, 0.1, 0.35]) translate([0, 0, land_height_mm]) cube([box_x_mm, box_y_mm, box_z_mm]);
}
