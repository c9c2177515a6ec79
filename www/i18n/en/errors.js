// English texts of the core's error reasons (src/error/message.rs, MESSAGES) as the page says
// them, after the field they concern ("the z component of e(u): the formula ends where an
// operand is expected (column 3)"): built by ui/errors.js from details.reason and
// details.args. tests/node/messages.test.mjs requires a text for every reason, in every
// language, with the same placeholders.
// Keys: error.*

export default {
  // how a sentence is put together
  'error.field': '{field}: {text}',
  'error.seeField': 'Something in “{field}” cannot be used: the message is beside the field.',
  'error.atColumn': '(column {column})',
  'error.atLine': '(line {line})',
  'error.atLineColumn': '(line {line}, column {column})',
  'error.hintJoin': '; {hint}',
  // when the page has no text for the reason: the kind of problem
  'error.code.invalid-argument': 'a value cannot be used here',
  'error.code.not-finite': 'a number is not finite',
  'error.code.out-of-range': 'a number is out of range',
  'error.code.too-large': 'this is more than ruledlab allows',
  'error.code.too-small': 'this is too little to compute with',
  'error.code.parse-error': 'this text cannot be read',
  'error.code.degenerate': 'the geometry is degenerate here',
  'error.code.not-converged': 'the solver did not converge',
  'error.code.singular': 'the system cannot be solved',
  'error.code.freed': 'this object has already been freed',
  'error.code.invalid-state': 'this object is busy with another call',
  'error.code.not-loaded': 'a part of the page could not be loaded (the connection?): try again, or reload the page',
  'error.code.no-webgl2': 'this browser does not provide WebGL2',
  'error.code.unknown': 'something went wrong',
  // what the core counts
  'error.what.rulings': 'rulings',
  'error.what.rulings in the CSV': 'rulings in the CSV',
  'error.what.rulings after subdivision': 'rulings after subdivision',
  'error.what.lines': 'lines',
  'error.what.lines after subdivision': 'lines after subdivision',
  'error.what.lines (rows × cols)': 'lines (rows × cols)',
  'error.what.points': 'points',
  'error.what.points (rulings) for this scheme': 'rulings for this scheme',
  'error.what.numbers in the JSON': 'numbers in the JSON',
  'error.what.bytes of JSON': 'bytes of JSON',
  'error.what.bytes of CSV': 'bytes of CSV',
  'error.what.characters': 'characters',
  'error.what.levels of nesting': 'levels of parentheses',
  'error.what.segment coordinates': 'segment coordinates',
  'error.what.point coordinates': 'point coordinates',
  'error.what.directrix points': 'directrix points',
  'error.what.pages': 'pages',
  // options the core names, as the page names them
  'error.option.csv': 'CSV',
  'error.option.json': 'JSON',
  'error.option.u': 'the interval of u',
  'error.option.v': 'the interval of v',
  // e(u) vanishing names e itself
  'error.option.e': '',
  'error.option.parameters': 'the parameters a, b, c',
  'error.option.coords': 'the lines',
  'error.option.lines': 'the lines',
  'error.option.h0': 'the convergence study',
  'error.option.surface': '',
  'error.option.rows': 'rows',
  'error.option.cols': 'columns',
  // the reasons
  'error.text': '{text}',
  'error.bad-length': '{what}: {len} numbers are not a whole number of items of {multiple}',
  'error.too-few': '{what}: {got} given, at least {min} needed',
  'error.too-many': '{what}: {got} is more than the limit of {max}',
  'error.not-finite-segment':
    'coordinate {coordinate} of ruling {item} is {value}; every coordinate must be a finite number',
  'error.not-finite-point':
    'coordinate {coordinate} of point {item} is {value}; every coordinate must be a finite number',
  'error.not-finite-line':
    'coordinate {coordinate} of line ({row}, {col}) is {value}; every coordinate must be a finite number',
  'error.out-of-range-segment':
    'coordinate {coordinate} of ruling {item} is {value}; magnitudes above {max} are not accepted',
  'error.out-of-range-point':
    'coordinate {coordinate} of point {item} is {value}; magnitudes above {max} are not accepted',
  'error.out-of-range-line':
    'coordinate {coordinate} of line ({row}, {col}) is {value}; magnitudes above {max} are not accepted',
  'error.zero-length': 'ruling {ruling} has zero length (its two endpoints coincide), so it has no direction',
  'error.text-too-long': '{got} {what} are more than the limit of {max}',
  'error.not-finite-at-u':
    'not finite at u = {u} (the value is {value}: a division by zero, or a function outside its domain?)',
  'error.not-finite-at-uv':
    'not finite at (u, v) = ({u}, {v}) (the value is {value}: a division by zero, or a function outside its domain?)',
  'error.derivative-not-finite-at-u':
    'the derivative is not finite at u = {u} (it is {value}), so the exact invariants do not exist there',
  'error.derivative-not-finite-at-uv':
    'the derivative is not finite at (u, v) = ({u}, {v}) (it is {value}), so the exact invariants do not exist there',
  'error.not-converged': 'the solver did not converge in {iterations} iterations',
  'error.singular': 'the system is not positive definite (pivot {pivot} is {value})',
  'error.formula-empty': 'the field is empty; write a formula such as cos(u)',
  'error.operator-before-number': 'an operator is missing before this number (write * for products)',
  'error.number-before-name': 'write {number}*{next}…, not {number}{next}… (products need *)',
  'error.operator-before-name': 'an operator is missing before “{name}” (write * for products)',
  'error.function-needs-parentheses': '{name} needs its argument in parentheses: {name}(…)',
  'error.not-a-function': '“{name}” is not a function; write {name}*(…) for a product',
  'error.unknown-function': 'there is no function “{name}”',
  'error.unknown-name': 'there is no name “{name}”',
  'error.known-names': 'known: {names}',
  'error.operator-before-parenthesis': 'an operator is missing before “(” (write * for products)',
  'error.unmatched-close': '“)” has no matching “(”',
  'error.empty-parentheses': 'the parentheses are empty',
  'error.operand-before': 'an operand is missing before “{sign}”',
  'error.atan2-arguments': 'atan2 takes two arguments: atan2(y, x)',
  'error.comma-outside-atan2': 'a comma separates only the two arguments of atan2(y, x)',
  'error.ambiguous-comma':
    '“{text}” could be two arguments or a decimal comma: write {point} for the number, or “{spaced}” (a space after the comma) for two arguments',
  'error.too-many-signs': 'more than {max} signs in a row',
  'error.operand-left': '“{sign}” needs an operand on its left',
  'error.operand-left-power': '“{sign}” needs an operand on its left (write ^ for powers)',
  'error.operand-left-comment': '“{sign}” needs an operand on its left (comments are not part of formulas)',
  'error.unexpected-character': 'the character “{char}” is not part of formulas ({hint})',
  'error.hint-pi': 'write pi',
  'error.hint-square': 'write ^2',
  'error.hint-cube': 'write ^3',
  'error.hint-times': 'write * for products',
  'error.hint-minus': 'write - (the ASCII minus)',
  'error.hint-divide': 'write / for quotients',
  'error.hint-brackets': 'use round parentheses',
  'error.hint-semicolon': 'separate the two arguments of atan2 with a comma: atan2(y, x)',
  'error.hint-grammar': 'formulas use numbers, names, + - * / ^, parentheses and commas',
  'error.never-closed': '“(” is never closed',
  'error.ends-expecting-operand': 'the formula ends where an operand is expected',
  'error.not-in-formulas': '“{operator}” is not part of formulas',
  'error.ambiguous-power': 'a^b^c is ambiguous',
  'error.power-parentheses': 'write (a^b)^c or a^(b^c)',
  'error.unreadable': 'the formula cannot be read',
  'error.interval-not-finite': 'needs two finite numbers, got [{lo}, {hi}]',
  'error.interval-order': 'the start must be less than the end, got [{lo}, {hi}]',
  'error.interval-equal': 'needs two different numbers, got [{lo}, {hi}]',
  'error.parameter-not-finite': '{name} must be a finite number, got {value}',
  'error.grid-size': 'must be a whole number from {min} to {max}, got {value}',
  'error.direction-vanishes-u': 'e(u) vanishes at u = {u}, so the ruling there has no direction',
  'error.direction-vanishes-uv': 'e(u, v) vanishes at (u, v) = ({u}, {v}), so the line there has no direction',
  'error.line-zero-length': 'line ({row}, {col}) has zero length (p = q), so it has no direction',
  'error.lines-cancel': 'a refined line has no direction: the weights cancel opposite lines',
  'error.parallel-at-step': 'the rulings at step {h} are parallel',
  'error.no-striction-point':
    'the surface has no striction point at u = {u}: the ruling there is cylindrical (its neighbours are parallel to it)',
  'error.not-a-number': '“{text}” is not a number',
  // developable strips and flat patterns
  'error.span-crosses-regression':
    'must start at 0 or beyond, got {from}: the strip would cross its edge of regression (or the apex)',
  'error.directrix-edge-zero':
    'points {edge} and {next} of the directrix coincide: the edge between them has no direction',
  'error.directrix-no-turn-at':
    'the directrix does not turn at point {point}: the lines of the edges meeting there coincide and bound no face',
  'error.directrix-straight': 'the directrix is straight: it turns nowhere, so it has no rectifying developable',
  'error.apex-not-finite': 'the apex must be three finite numbers',
  'error.apex-on-directrix': 'the apex lies on point {point} of the directrix: the ruling there has no direction',
  'error.apex-in-line':
    'points {edge} and {next} of the directrix are in line with the apex: the face between their rulings has no width',
  'error.direction-zero': 'must be a nonzero vector of finite numbers',
  'error.edge-along-rulings': 'edge {edge} of the directrix runs along the rulings: the face there has no width',
  'error.edge-along-ruling':
    'the edge of the directrix at point {point} runs along the ruling there: the next ruling is not defined',
  'error.not-developable':
    'rulings {i} and {j} are not coplanar (an end lies {height} off the plane of the other three, more than {max}; δ = {delta}): the strip is not developable; Section 3’s approximate development maps it with gaps',
  'error.rulings-collinear': 'rulings {i} and {j} lie on one line: the face between them has no width',
  'error.out-of-interval': 'must be a number from {min} to {max}, got {value}',
  'error.pattern-points': 'needs {need} numbers (x, y of both ends of every ruling), got {got}',
  'error.sheet-too-large':
    'the sheet would be {width} × {height} mm, more than {max} mm a side: choose fewer millimetres per unit',
  'error.paper-too-small': 'a page of {width} × {height} mm leaves no room inside its margins',
  'error.not-finite-number': '{text} is not a finite number',
  'error.csv-six-numbers': 'a line needs 6 numbers (a.x a.y a.z b.x b.y b.z), this one has {found}',
  'error.csv-no-data': 'there is no line of 6 numbers in it',
  'error.import-too-few':
    '{found:line:lines} of 6 numbers: at least 2 are needed (a ruled surface has two rulings or more)',
  'error.import-zero-length': 'the two endpoints of this line coincide: a ruling needs two different points',
  'error.json-too-deep': 'nested deeper than {max} levels',
  'error.json-end': 'the text ends too early',
  'error.json-array-separator': '“,” or “]” expected in an array',
  'error.json-string-key': 'a key in quotes expected',
  'error.json-colon': '“:” expected after a key',
  'error.json-object-separator': '“,” or “}” expected in an object',
  'error.json-unterminated': 'a string is not closed',
  'error.json-word': 'a word that JSON does not know',
  'error.json-character': 'the character “{char}” does not belong here',
  'error.json-trailing': 'there is more text after the JSON value',
  'error.json-segments-missing': 'an object needs a “segments” array',
  'error.json-grid-integer': '“{key}” must be a whole number from 2 to {max}',
  'error.json-rows-and-cols': 'give both “rows” and “cols”, or neither',
  'error.json-segments-array': '“segments” must be an array',
  'error.json-segment-six': 'a segment needs 6 numbers, this one has {found}',
  'error.json-number': 'a number expected',
  'error.json-segment': '[ax, ay, az, bx, by, bz] expected',
  'error.json-whole-segments': '{count} numbers are not a whole number of segments (6 each)',
  'error.json-grid-count': 'a {rows} × {cols} grid needs {need} segments, there are {found}',
  'error.import-zero-axis': 'pose {record} has a zero tool axis (i = j = k = 0), so it has no direction',
  'error.import-too-few-poses': '{found} pose(s): at least 2 are needed (a tool path has two poses or more)',
  'error.json-poses-missing': 'an object needs a "poses" array',
  'error.json-poses-array': 'poses must be an array',
  'error.json-pose': 'expected a pose: an object with "tip": [x, y, z] and "axis": [i, j, k]',
  'error.pose-orientation': 'pose {pose}: no setting of the rotary axes of {machine} gives this tool axis',
  'error.pose-unreachable': 'pose {pose} cannot be reached: {axis} would be {value}, outside its limits {min} to {max}',
  'error.linearisation-tolerance':
    'between poses {pose} and {next} the linear interpolation still strays {deviation} mm from the path after {rounds} rounds of inserted poses (tolerance {tolerance} mm): the rotary axes turn over or pass the pole there',
  'error.flip-in-cut':
    'between poses {pose} and {next} the rotary axes flip inside the cut: {tilt} from {from} to {to} while the tool axis turns {angle}°, because staying on the same side takes {axis} to {value}, at or beyond its limits {min} to {max}; widen {axis}’s limits, turn the part or split the cut there',
  'error.flip-in-cut-free':
    'between poses {pose} and {next} the rotary axes flip inside the cut: {tilt} from {from} to {to} while the tool axis turns {angle}°; split the cut there',
  'error.retract-horizontal':
    'pose {pose}: the tool axis is too close to horizontal to retract along it to the safe height',
  'error.approach-blocked':
    'pose {pose}: no point on its tool axis within the machine’s travel from which the tool comes down clear of the stock (what stays in the stock or stops it: the {part})',
  'error.unwind-blocked':
    'pose {pose}: a rotary axis must unwind here, and no point on the tool axis within the travel lets it turn clear of the stock',
  'error.warn-duplicate-pose': 'pose {pose} repeats pose {previous}: no block written for it',
  'error.warn-flipped-axis':
    'pose {pose}: the tool axis turns {angle}° from pose {previous}; is it flipped, pointing away from the spindle?',
  'error.warn-slowed':
    '{count} blocks slowed by the axes’ limits, the slowest at {feed} {units}/min at the tip instead of {wanted} ({axis}, pose {pose})',
  'error.warn-acceleration': '{count} blocks still need more acceleration than an axis has, from pose {pose}',
  'error.warn-pole-cone':
    '{count} poses within {cone}° of the pole, from pose {pose}: their tool axis turned by up to {angle}° to keep the rotary axes smooth',
  'error.warn-tool-in-stock':
    'the {part} enters the stock at pose {pose} ({count} poses of the cut), by up to {depth} {units}',
  'error.csv-pose-numbers': 'expected 6 numbers for a pose (tip x, y, z and tool axis i, j, k), found {found}',
  'error.csv-pose-angles': 'expected a number in each of the columns {columns}, found {found} numbers',
  'error.pose-angles-machine':
    'the poses give rotary angles ({columns}): name the machine they are for (a line “# machine: <name>” or the machine chosen)',
  'error.pose-header-unknown':
    'the header {columns} names no tool pose: name the tip’s columns x, y, z (or tip_x, tip_y, tip_z) and the tool axis’s i, j, k (or axis_i, axis_j, axis_k; from the tip towards the spindle), or x, y, z and rotary angles a, b, c for a machine; without a header each line is tip x, y, z and axis i, j, k',
  'error.pose-angles-letter': 'the machine {machine} has no rotary axis {letter}, which the column {letter} gives',
  'error.target-too-few': '{found} target point(s): at least 2 are needed (a target curve)',
  'error.target-three-numbers': 'expected 3 numbers for a target point (x, y, z), found {found}',
  'error.target-json': 'expected an array of points [x, y, z], or an object with "points"',
  'error.target-json-point': 'expected a target point [x, y, z]',
  'error.units-unknown':
    'the file’s units "{said}" are not known: write mm or inch (millimetres, millimeters, in or inches are read too)',
  'error.part-holder': 'holder',
  'error.part-shank': 'shank',
};
