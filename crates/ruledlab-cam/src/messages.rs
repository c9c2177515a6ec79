//! The CAM crate's messages: each a stable *reason* with named arguments and its English text
//! ([`CAM_MESSAGES`]), as the geometry's are in `ruledlab::MESSAGES`. The English is the API's;
//! a page speaking another language builds its own sentence from the reason and the arguments
//! (the page's language files have a text for every reason of both catalogues:
//! tests/node/messages.test.mjs).

use ruledlab::Catalogue;

/// `msg!("pose-unreachable", pose = 3)`: a [`ruledlab::Message`] of this crate's catalogue.
#[macro_export]
macro_rules! msg {
    ($reason:literal $(, $name:ident = $value:expr)* $(,)?) => {
        ::ruledlab::Message::of($crate::CAM_MESSAGES, $reason)$(.with(stringify!($name), $value))*
    };
}

/// Every reason of the CAM crate with its English template (`{name}`: an argument). The page's
/// language files (www/i18n) have a text for each, under `error.<reason>`.
pub const CAM_MESSAGES: Catalogue = &[
    // tool poses (poses.rs)
    ("import-zero-axis", "pose {record} has a zero tool axis (i = j = k = 0), so it has no direction"),
    ("import-too-few-poses", "{found} pose(s): at least 2 are needed (a tool path has two poses or more)"),
    ("json-poses-missing", "an object needs a \"poses\" array"),
    ("json-poses-array", "poses must be an array"),
    ("json-pose", "expected a pose: an object with \"tip\": [x, y, z] and \"axis\": [i, j, k]"),
    ("csv-pose-numbers", "expected 6 numbers for a pose (tip x, y, z and tool axis i, j, k), found {found}"),
    ("csv-pose-angles", "expected a number in each of the columns {columns}, found {found} numbers"),
    ("pose-angles-machine", "the poses give rotary angles ({columns}): name the machine they are for (a line \"# machine: <name>\" or the machine chosen)"),
    ("pose-header-unknown", "the header {columns} names no tool pose: name the tip's columns x, y, z (or tip_x, tip_y, tip_z) and the tool axis's i, j, k (or axis_i, axis_j, axis_k; from the tip towards the spindle), or x, y, z and rotary angles a, b, c for a machine; without a header each line is tip x, y, z and axis i, j, k"),
    ("pose-angles-letter", "the machine {machine} has no rotary axis {letter}, which the column {letter} gives"),
    // target curves (target_curve.rs)
    ("target-too-few", "{found} target point(s): at least 2 are needed (a target curve)"),
    ("target-three-numbers", "expected 3 numbers for a target point (x, y, z), found {found}"),
    ("target-json", "expected an array of points [x, y, z], or an object with \"points\""),
    ("target-json-point", "expected a target point [x, y, z]"),
    // the units a file says (units.rs)
    ("units-unknown", "the file's units \"{said}\" are not known: write mm or inch (millimetres, millimeters, in or inches are read too)"),
    // the G-code post (post/, kinematics.rs, solve.rs, linearise.rs)
    ("pose-orientation", "pose {pose}: no setting of the rotary axes of {machine} gives this tool axis"),
    ("pose-unreachable", "pose {pose} cannot be reached: {axis} would be {value}, outside its limits {min} to {max}"),
    (
        "linearisation-tolerance",
        "between poses {pose} and {next} the controller's linear interpolation still strays {deviation} mm from the path after {rounds} rounds of inserted poses (tolerance {tolerance} mm): the rotary axes turn over or pass the pole there",
    ),
    (
        "flip-in-cut",
        "between poses {pose} and {next} the rotary axes flip inside the cut: {tilt} from {from} to {to} while the tool axis turns {angle}°, because staying on the same side takes {axis} to {value}, at or beyond its limits {min} to {max}; widen {axis}'s limits, turn the part or split the cut there",
    ),
    (
        "flip-in-cut-free",
        "between poses {pose} and {next} the rotary axes flip inside the cut: {tilt} from {from} to {to} while the tool axis turns {angle}°; split the cut there",
    ),
    ("retract-horizontal", "pose {pose}: the tool axis is too close to horizontal to retract along it to the safe height"),
    ("approach-blocked", "pose {pose}: no point on its tool axis within the machine's travel from which the tool comes down clear of the stock (what stays in the stock or stops it: the {part})"),
    ("unwind-blocked", "pose {pose}: a rotary axis must unwind here, and no point on the tool axis within the travel lets it turn clear of the stock"),
    // what the G-code post warns of (post/plan.rs)
    ("warn-duplicate-pose", "pose {pose} repeats pose {previous}: no block written for it"),
    ("warn-flipped-axis", "pose {pose}: the tool axis turns {angle}° from pose {previous}; is it flipped, pointing away from the spindle?"),
    ("warn-slowed", "{count} blocks slowed by the axes' limits, the slowest at {feed} {units}/min at the tip instead of {wanted} ({axis}, pose {pose})"),
    ("warn-acceleration", "{count} blocks still need more acceleration than an axis has, from pose {pose}"),
    ("warn-pole-cone", "{count} poses within {cone}° of the pole, from pose {pose}: their tool axis turned by up to {angle}° to keep the rotary axes smooth"),
    ("warn-tool-in-stock", "the {part} enters the stock at pose {pose} ({count} poses of the cut), by up to {depth} {units}"),
    ("part-holder", "holder"),
    ("part-shank", "shank"),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_reason_once_in_both_catalogues_and_said_in_english() {
        for (i, (reason, _)) in CAM_MESSAGES.iter().enumerate() {
            assert!(CAM_MESSAGES[..i].iter().all(|(r, _)| r != reason), "{reason} twice");
            assert!(ruledlab::message_template(reason).is_none(), "{reason} is the core's too");
        }
        let m = crate::msg!("pose-unreachable", pose = 3usize, axis = "A", value = 130.0, min = -30.0, max = 120.0);
        assert_eq!(m.english(), "pose 3 cannot be reached: A would be 130, outside its limits -30 to 120");
    }
}
