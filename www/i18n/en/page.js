// English texts of the page around the view: its title and pickers, the Share dialog, import and
// export, the messages when it cannot start, the <ruled-view> element's notes and the notes on
// values of the link that were not used.
// Keys: app.*, boot.*, share.*, io.*, export.*, element.*, note.*

export default {
  // the page
  'app.title': 'ruledlab',
  'app.subtitle': 'Discrete models of ruled surfaces and line congruences, after Odehnal & Pottmann',
  'app.scene': 'Scene',
  'app.language': 'Language',
  'app.figures': 'Figures of the paper',
  'app.share': 'Share',
  'app.onefile': 'Download this view as one HTML file',
  'app.onefileMissing': 'The one-file build is not here: run npm run build, or use the downloaded ruledlab.html.',
  'app.skip': 'Skip to the controls',
  'app.exercises': 'Exercises',
  'app.menu': 'Menu',

  'boot.noWebgl2':
    'ruledlab could not start: this browser (or this device) does not provide WebGL2, which the 3D view needs. Current Firefox, Chrome, Edge and Safari provide it; a browser with hardware acceleration turned off may not.',
  'boot.cspWasm':
    "ruledlab could not start: the page it is in forbids WebAssembly. Its Content-Security-Policy needs 'wasm-unsafe-eval' in script-src (ruledlab’s book: “In a course system”).",
  'boot.noWasm':
    'ruledlab could not start: this browser cannot run its WebAssembly (it needs WebAssembly with SIMD: Chrome 91, Firefox 89, Safari 16.4 or later).',
  'boot.load':
    'ruledlab could not start: one of its files did not load. Reload the page; if it is shown inside another page, that page may block it.',
  'boot.technical': 'What the browser said',
  'boot.failed': 'ruledlab could not start.',

  'share.title': 'Share this view',
  'share.intro': 'Each carries the current scene, its parameters, the language and the camera.',
  'share.introTask':
    'Each carries the exercise, the language and what readers may do — not this view’s camera or the answers typed here; each reader draws her own numbers.',
  'share.fromFile':
    'This page was opened from a file, so it has no address that others could open. To share this view, download it as one HTML file and upload that to your course page, or put the element below into a page of your own.',
  'share.noAddress':
    'This view is shown inside another page and has no address of its own that others could open. To share it, download it as one HTML file, or put the element below into a page of your own.',
  'share.elementServed':
    'The script comes from this site and loads on pages of any other site; copy it to your own server if this one may go away.',
  'share.elementModule':
    'This site has no one-file build (npm run build makes it), so the snippet loads the module ruledlab/view: that works on other sites only if this server allows them to load its scripts (Access-Control-Allow-Origin).',
  'share.elementUpload':
    'Upload {file} (the button below downloads it) next to your page. If it sits elsewhere, change src="{file}" to its address.',
  'share.embedDownload': 'Download {file}',
  'share.embedMissing': 'This copy of the page cannot hand out {file}; take it from dist/ of the ruledlab package.',
  'share.onefileNote':
    'The whole page with this view in one file: it works opened from disk and uploaded to a course system.',
  'share.framed':
    'If nothing is saved, the page around this view does not allow downloads: open the view on a page of its own.',
  'share.copyWhat': 'Copy: {what}',
  'share.selectCopy': 'Selected: press Ctrl+C (⌘C) to copy.',
  'share.link': 'Link',
  'share.taskLink': 'Link to the exercise',
  'share.iframe': 'Embed with an iframe',
  'share.element': 'Embed with <ruled-view>',
  'share.copy': 'Copy',
  'share.copied': 'Copied.',
  'share.close': 'Close',
  'share.editTooLarge':
    'Your edit has more than {max} points: the link and the snippets do not carry it (the one-file download does).',

  'io.summary': 'Import and export',
  'io.paste': 'Paste CSV (6 numbers per ruling or tool pose) or JSON',
  'io.upload': 'Upload a CSV or JSON file',
  'io.show': 'Show in the view',
  'io.staleExample': 'The example data stays on screen.',
  'io.stale': 'The data shown is the previous import: this text could not be read.',
  'io.notStored':
    'This import has more than {max} rulings: too many for the link, and this page has no storage here (it is shown in a sandboxed frame), so it lasts until the page is closed.',
  'io.stored':
    'This import has more than {max} rulings: it is kept in this tab\u2019s session storage, not in the link.',
  'io.exports': 'Save what is shown',
  'io.printWidth': 'Printed width of SVG and TikZ figures (cm)',
  'io.kind': 'The text holds',
  'io.kind.auto': 'recognise it',
  'io.kind.segments': 'segments (rulings, lines)',
  'io.kind.poses': 'tool poses (tip x, y, z and tool axis i, j, k; or x, y, z and rotary angles a, b, c)',
  'io.kind.target': 'a target curve for the tool poses (x, y, z)',
  'io.units': 'in',
  'io.unitsName': 'in: the units of the tool poses',
  'io.units.auto': 'the file’s units (millimetres unless it says)',
  'io.units.mm': 'millimetres',
  'io.units.inch': 'inches',
  'io.targetNeedsPoses': 'A target curve is measured against your tool poses: import them first.',
  'io.heldInTask':
    'The data files (OBJ, CSV, JSON, invariants) can be saved once you leave the exercise: they would hold the answer.',

  'export.png': 'PNG',
  'export.svg': 'Figure (SVG)',
  'export.svgBw': 'Figure (SVG, black and white)',
  'export.tikz': 'Figure (TikZ)',
  'export.tikzBw': 'Figure (TikZ, black and white)',
  'export.png2': 'PNG 2×',
  'export.png4': 'PNG 4×',
  'export.obj': 'OBJ',
  'export.csv': 'CSV',
  'export.json': 'JSON',
  'export.invariants': 'Invariants JSON',
  'export.invariantsCsv': 'Invariants CSV',
  'export.plot': 'Plot (SVG)',

  'element.unknownScene': 'There is no scene “{scene}”. The scenes are: {known}.',
  'element.unknownPaper': 'There is no figure or example of the paper called “{paper}”. They are: {known}.',
  'element.note.notOnOff': 'The value of “{key}” in the params attribute is not on or off; its default is used.',
  'element.note.notNumber': 'The value of “{key}” in the params attribute is not a number; its default is used.',
  'element.note.clamped':
    'The value of “{key}” in the params attribute is out of range; the nearest allowed value is used.',
  'element.note.unknownChoice':
    'The value of “{key}” in the params attribute is not one of the choices; its default is used.',
  'element.note.tooLong': 'The value of “{key}” in the params attribute is too long; its default is used.',
  'element.note.unknownParam': 'This scene has no parameter “{key}”; its parameters are: {known}.',
  // the same, for a value given to setParams()
  'element.set.notOnOff': 'The value setParams was given for “{key}” is not on or off; its default is used.',
  'element.set.notNumber': 'The value setParams was given for “{key}” is not a number; its default is used.',
  'element.set.clamped':
    'The value setParams was given for “{key}” is out of range; the nearest allowed value is used.',
  'element.set.unknownChoice':
    'The value setParams was given for “{key}” is not one of the choices; its default is used.',
  'element.set.tooLong': 'The value setParams was given for “{key}” is too long; its default is used.',
  'element.set.unknownParam': 'This scene has no parameter “{key}”; its parameters are: {known}.',
  'element.note.badInput': 'The input attribute does not fit this scene; the built-in input is shown.',
  'element.note.badKlein':
    'The klein attribute is not three numbers α,β,ℓ; the Klein view is drawn in the scene\u2019s own image.',
  'element.note.kleinHeld':
    'A number of the klein attribute lay outside its range or between its steps and is held at the nearest value the Klein view’s slider takes.',
  'element.badCamera':
    'The camera attribute could not be read (six numbers: yaw, pitch, distance, x, y, z); the view is fitted to the scene.',
  'element.note.badTask': 'The task attribute could not be read ({reason}); the scene is shown without it.',
  'element.note.badSolution':
    'The solution attribute is not \u201cnever\u201d or a whole number of checks from 0 to {max}; the solution is offered after a first check.',
  'element.note.badSeed': 'The seed attribute is not a whole number from 0 to {max}; new numbers were drawn.',

  // values the link could not use
  'note.notOnOff': 'The link\u2019s value of “{key}” is not on or off; its default is used.',
  'note.notNumber': 'The link\u2019s value of “{key}” is not a number; its default is used.',
  'note.clamped': 'The link\u2019s value of “{key}” is out of range; the nearest allowed value is used.',
  'note.unknownChoice': 'The link\u2019s value of “{key}” is not one of the choices; its default is used.',
  'note.tooLong': 'The link\u2019s value of “{key}” is too long; its default is used.',
  'note.linkTooLong': 'This link is longer than {max} KiB and was not read; the page starts at its defaults.',
  'note.unknownScene': 'The link names a scene that does not exist; the first scene is shown.',
  'note.badCamera': 'The link\u2019s camera could not be read; the view is fitted to the scene.',
  'note.badKlein':
    'The link\u2019s image for the Klein view is not three numbers α,β,ℓ; the Klein view is drawn in the scene\u2019s own image.',
  'note.kleinHeld':
    'A number of the link\u2019s image for the Klein view lay outside its range or between its steps and is held at the nearest value the Klein view’s slider takes.',
  'note.badData': 'The link\u2019s data could not be read; the example data is shown.',
  'note.unknownFigure':
    'The link names a figure of the paper that ruledlab does not know; the scene is shown without it.',
  'note.badInput': 'The edited input in the link does not fit this scene; the built-in input is shown.',
  'note.badTask': 'The exercise in the link could not be read ({reason}); the scene is shown without it.',
  'note.badSeed': 'The link\u2019s seed is not a whole number from 0 to {max}; new numbers were drawn.',
  'note.badSolution':
    'The link\u2019s solution rule is not \u201cnever\u201d or a whole number of checks from 0 to {max}; the solution is offered after a first check.',
};
