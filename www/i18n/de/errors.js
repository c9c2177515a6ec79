// Die Fehlergründe des Kerns (src/error/message.rs, MESSAGES) auf Deutsch, nach dem Feld, das
// sie betreffen („z-Komponente von e(u): Die Formel endet, wo ein Operand erwartet wird
// (Spalte 3).“); ui/errors.js setzt sie aus details.reason und details.args zusammen.
// tests/node/messages.test.mjs verlangt für jeden Grund einen Text mit denselben Platzhaltern.
// Keys: error.*

export default {
  'error.field': '{field}: {text}',
  'error.seeField': 'In „{field}“ stimmt etwas nicht: Die Meldung steht beim Feld.',
  'error.atColumn': '(Spalte {column})',
  'error.atLine': '(Zeile {line})',
  'error.atLineColumn': '(Zeile {line}, Spalte {column})',
  'error.hintJoin': '; {hint}',
  'error.code.invalid-argument': 'Ein Wert ist hier nicht verwendbar',
  'error.code.not-finite': 'Eine Zahl ist nicht endlich',
  'error.code.out-of-range': 'Eine Zahl liegt außerhalb des erlaubten Bereichs',
  'error.code.too-large': 'Das ist mehr, als ruledlab erlaubt',
  'error.code.too-small': 'Das ist zu wenig, um damit zu rechnen',
  'error.code.parse-error': 'Dieser Text ist nicht lesbar',
  'error.code.degenerate': 'Die Geometrie ist hier ausgeartet',
  'error.code.not-converged': 'Das Lösungsverfahren ist nicht konvergiert',
  'error.code.singular': 'Das Gleichungssystem ist nicht lösbar',
  'error.code.freed': 'Dieses Objekt ist bereits freigegeben',
  'error.code.invalid-state': 'Dieses Objekt ist mit einem anderen Aufruf beschäftigt',
  'error.code.not-loaded':
    'Ein Teil der Seite konnte nicht geladen werden (die Verbindung?): bitte noch einmal versuchen oder die Seite neu laden',
  'error.code.no-webgl2': 'Dieser Browser bietet kein WebGL2',
  'error.code.unknown': 'Etwas ist schiefgegangen',
  'error.what.rulings': 'Erzeugende',
  'error.what.rulings in the CSV': 'Erzeugende in der CSV-Datei',
  'error.what.rulings after subdivision': 'Erzeugende nach der Unterteilung',
  'error.what.lines': 'Geraden',
  'error.what.lines after subdivision': 'Geraden nach der Unterteilung',
  'error.what.lines (rows × cols)': 'Geraden (Zeilen × Spalten)',
  'error.what.points': 'Punkte',
  'error.what.points (rulings) for this scheme': 'Erzeugende für dieses Schema',
  'error.what.numbers in the JSON': 'Zahlen im JSON',
  'error.what.bytes of JSON': 'Bytes JSON',
  'error.what.bytes of CSV': 'Bytes CSV',
  'error.what.characters': 'Zeichen',
  'error.what.levels of nesting': 'Klammerebenen',
  'error.what.segment coordinates': 'Koordinaten der Strecken',
  'error.what.point coordinates': 'Koordinaten der Punkte',
  'error.what.directrix points': 'Punkte der Leitkurve',
  'error.what.pages': 'Seiten',
  'error.option.csv': 'CSV',
  'error.option.json': 'JSON',
  'error.option.u': 'Bereich von u',
  'error.option.v': 'Bereich von v',
  // e(u) vanishing names e itself
  'error.option.e': '',
  'error.option.parameters': 'Parameter a, b, c',
  'error.option.coords': 'Geraden',
  'error.option.lines': 'Geraden',
  'error.option.h0': 'Konvergenzstudie',
  'error.option.surface': '',
  'error.option.rows': 'Zeilen',
  'error.option.cols': 'Spalten',
  'error.text': '{text}',
  'error.bad-length': '{what}: {len} Zahlen ergeben keine ganze Zahl von Einträgen zu je {multiple}',
  'error.too-few': '{what}: {got} angegeben, mindestens {min} nötig',
  'error.too-many': '{what}: {got} sind mehr als die Grenze von {max}',
  'error.not-finite-segment':
    'Koordinate {coordinate} der Erzeugenden {item} ist {value}; jede Koordinate muss eine endliche Zahl sein',
  'error.not-finite-point':
    'Koordinate {coordinate} des Punktes {item} ist {value}; jede Koordinate muss eine endliche Zahl sein',
  'error.not-finite-line':
    'Koordinate {coordinate} der Geraden ({row}, {col}) ist {value}; jede Koordinate muss eine endliche Zahl sein',
  'error.out-of-range-segment':
    'Koordinate {coordinate} der Erzeugenden {item} ist {value}; Beträge über {max} sind nicht zulässig',
  'error.out-of-range-point':
    'Koordinate {coordinate} des Punktes {item} ist {value}; Beträge über {max} sind nicht zulässig',
  'error.out-of-range-line':
    'Koordinate {coordinate} der Geraden ({row}, {col}) ist {value}; Beträge über {max} sind nicht zulässig',
  'error.zero-length':
    'Die Erzeugende {ruling} hat die Länge null (ihre Endpunkte fallen zusammen) und damit keine Richtung',
  'error.text-too-long': '{got} {what} sind mehr als die Grenze von {max}',
  'error.not-finite-at-u':
    'Nicht endlich bei u = {u} (der Wert ist {value}, also keine Zahl oder unendlich: eine Division durch null oder eine Funktion außerhalb ihres Definitionsbereichs?)',
  'error.not-finite-at-uv':
    'Nicht endlich bei (u; v) = ({u}; {v}) (der Wert ist {value}, also keine Zahl oder unendlich: eine Division durch null oder eine Funktion außerhalb ihres Definitionsbereichs?)',
  'error.derivative-not-finite-at-u':
    'Die Ableitung ist bei u = {u} nicht endlich (sie ist {value}); die exakten Invarianten gibt es dort nicht',
  'error.derivative-not-finite-at-uv':
    'Die Ableitung ist bei (u; v) = ({u}; {v}) nicht endlich (sie ist {value}); die exakten Invarianten gibt es dort nicht',
  'error.not-converged': 'Das Lösungsverfahren ist in {iterations} Iterationen nicht konvergiert',
  'error.singular': 'Das System ist nicht positiv definit (Pivot {pivot} ist {value})',
  'error.formula-empty': 'Das Feld ist leer; schreiben Sie eine Formel wie cos(u)',
  'error.operator-before-number': 'Vor dieser Zahl fehlt ein Operator (für Produkte * schreiben)',
  'error.number-before-name': 'Schreiben Sie {number}*{next}…, nicht {number}{next}… (Produkte brauchen *)',
  'error.operator-before-name': 'Vor „{name}“ fehlt ein Operator (für Produkte * schreiben)',
  'error.function-needs-parentheses': '{name} braucht sein Argument in Klammern: {name}(…)',
  'error.not-a-function': '„{name}“ ist keine Funktion; für ein Produkt {name}*(…) schreiben',
  'error.unknown-function': 'Eine Funktion „{name}“ gibt es nicht',
  'error.unknown-name': 'Einen Namen „{name}“ gibt es nicht',
  'error.known-names': 'bekannt sind: {names}',
  'error.operator-before-parenthesis': 'Vor „(“ fehlt ein Operator (für Produkte * schreiben)',
  'error.unmatched-close': 'Zu „)“ gibt es kein passendes „(“',
  'error.empty-parentheses': 'Die Klammern sind leer',
  'error.operand-before': 'Vor „{sign}“ fehlt ein Operand',
  'error.atan2-arguments': 'atan2 hat zwei Argumente: atan2(y, x)',
  'error.comma-outside-atan2': 'Ein Komma trennt nur die beiden Argumente von atan2(y, x)',
  'error.ambiguous-comma':
    '„{text}“ kann zwei Argumente oder ein Dezimalkomma sein: Schreiben Sie {point} für die Zahl oder „{spaced}“ (mit Leerzeichen nach dem Komma) für zwei Argumente',
  'error.too-many-signs': 'Mehr als {max} Vorzeichen hintereinander',
  'error.operand-left': '„{sign}“ braucht links einen Operanden',
  'error.operand-left-power': '„{sign}“ braucht links einen Operanden (Potenzen schreibt man mit ^)',
  'error.operand-left-comment': '„{sign}“ braucht links einen Operanden (Kommentare gehören nicht in Formeln)',
  'error.unexpected-character': 'Das Zeichen „{char}“ gehört nicht zu den Formeln ({hint})',
  'error.hint-pi': 'schreiben Sie pi',
  'error.hint-square': 'schreiben Sie ^2',
  'error.hint-cube': 'schreiben Sie ^3',
  'error.hint-times': 'für Produkte * schreiben',
  'error.hint-minus': 'schreiben Sie - (das ASCII-Minus)',
  'error.hint-divide': 'für Quotienten / schreiben',
  'error.hint-brackets': 'verwenden Sie runde Klammern',
  'error.hint-semicolon': 'die beiden Argumente von atan2 trennt ein Komma: atan2(y, x)',
  'error.hint-grammar': 'Formeln bestehen aus Zahlen, Namen, + - * / ^, Klammern und Kommas',
  'error.never-closed': '„(“ wird nie geschlossen',
  'error.ends-expecting-operand': 'Die Formel endet, wo ein Operand erwartet wird',
  'error.not-in-formulas': '„{operator}“ gehört nicht zu den Formeln',
  'error.ambiguous-power': 'a^b^c ist mehrdeutig',
  'error.power-parentheses': 'schreiben Sie (a^b)^c oder a^(b^c)',
  'error.unreadable': 'Die Formel ist nicht lesbar',
  'error.interval-not-finite': 'Braucht zwei endliche Zahlen; angegeben ist [{lo}; {hi}]',
  'error.interval-order': 'Der Anfang muss kleiner als das Ende sein; angegeben ist [{lo}; {hi}]',
  'error.interval-equal': 'Braucht zwei verschiedene Zahlen; angegeben ist [{lo}; {hi}]',
  'error.parameter-not-finite': '{name} muss eine endliche Zahl sein; angegeben ist {value}',
  'error.grid-size': 'Muss eine ganze Zahl von {min} bis {max} sein; angegeben ist {value}',
  'error.direction-vanishes-u': 'e(u) verschwindet bei u = {u}; die Erzeugende dort hat keine Richtung',
  'error.direction-vanishes-uv': 'e(u, v) verschwindet bei (u; v) = ({u}; {v}); die Gerade dort hat keine Richtung',
  'error.line-zero-length': 'Die Gerade ({row}, {col}) hat die Länge null (p = q) und damit keine Richtung',
  'error.lines-cancel': 'Eine verfeinerte Gerade hat keine Richtung: Die Gewichte heben entgegengesetzte Geraden auf',
  'error.parallel-at-step': 'Die Erzeugenden im Schritt {h} sind parallel',
  'error.no-striction-point':
    'Die Fläche hat bei u = {u} keinen Kehlpunkt: Die Erzeugende dort ist zylindrisch (ihre Nachbarn sind zu ihr parallel)',
  'error.not-a-number': '„{text}“ ist keine Zahl',
  // abwickelbare Streifen und Schnittmuster
  'error.span-crosses-regression':
    'muss bei 0 oder später beginnen, angegeben ist {from}: Der Streifen ginge über seine Gratlinie (oder die Spitze) hinaus',
  'error.directrix-edge-zero':
    'Die Punkte {edge} und {next} der Leitkurve fallen zusammen: Die Kante zwischen ihnen hat keine Richtung',
  'error.directrix-no-turn-at':
    'Die Leitkurve knickt im Punkt {point} nicht: Die Geraden der dort zusammentreffenden Kanten fallen zusammen und begrenzen keine Fläche',
  'error.directrix-straight': 'Die Leitkurve ist gerade: Sie knickt nirgends und hat daher keine rektifizierende Torse',
  'error.apex-not-finite': 'Die Spitze müssen drei endliche Zahlen sein',
  'error.apex-on-directrix':
    'Die Spitze liegt auf dem Punkt {point} der Leitkurve: Die Erzeugende dort hat keine Richtung',
  'error.apex-in-line':
    'Die Punkte {edge} und {next} der Leitkurve liegen mit der Spitze auf einer Geraden: Die Fläche zwischen ihren Erzeugenden hat keine Breite',
  'error.direction-zero': 'muss ein vom Nullvektor verschiedener Vektor aus endlichen Zahlen sein',
  'error.edge-along-rulings':
    'Die Kante {edge} der Leitkurve verläuft entlang der Erzeugenden: Die Fläche dort hat keine Breite',
  'error.edge-along-ruling':
    'Die Kante der Leitkurve im Punkt {point} verläuft entlang der Erzeugenden dort: Die nächste Erzeugende ist nicht bestimmt',
  'error.not-developable':
    'Die Erzeugenden {i} und {j} liegen nicht in einer Ebene (ein Ende liegt {height} neben der Ebene der anderen drei, mehr als {max}; δ = {delta}): Der Streifen ist nicht abwickelbar; die näherungsweise Abwicklung aus Abschnitt 3 bildet ihn mit Lücken ab',
  'error.rulings-collinear':
    'Die Erzeugenden {i} und {j} liegen auf einer Geraden: Die Fläche zwischen ihnen hat keine Breite',
  'error.out-of-interval': 'muss eine Zahl von {min} bis {max} sein, angegeben ist {value}',
  'error.pattern-points': 'braucht {need} Zahlen (x, y beider Enden jeder Erzeugenden), angegeben sind {got}',
  'error.sheet-too-large':
    'Der Bogen würde {width} × {height} mm groß, mehr als {max} mm je Seite: weniger Millimeter je Einheit wählen',
  'error.paper-too-small': 'Eine Seite von {width} × {height} mm lässt innerhalb ihrer Ränder keinen Platz',
  'error.not-finite-number': '{text} ist keine endliche Zahl',
  'error.csv-six-numbers': 'Eine Zeile braucht 6 Zahlen (a.x a.y a.z b.x b.y b.z), diese hat {found}',
  'error.csv-no-data': 'Sie enthält keine Zeile mit 6 Zahlen',
  'error.import-too-few':
    '{found:Zeile:Zeilen} mit 6 Zahlen: Nötig sind mindestens 2 (eine Regelfläche hat zwei Erzeugende oder mehr)',
  'error.import-zero-length':
    'Die beiden Endpunkte in dieser Zeile fallen zusammen: Eine Erzeugende braucht zwei verschiedene Punkte',
  'error.json-too-deep': 'Tiefer als {max} Ebenen verschachtelt',
  'error.json-end': 'Der Text endet zu früh',
  'error.json-array-separator': '„,“ oder „]“ in einem Array erwartet',
  'error.json-string-key': 'Ein Schlüssel in Anführungszeichen erwartet',
  'error.json-colon': '„:“ nach einem Schlüssel erwartet',
  'error.json-object-separator': '„,“ oder „}“ in einem Objekt erwartet',
  'error.json-unterminated': 'Eine Zeichenkette ist nicht geschlossen',
  'error.json-word': 'Ein Wort, das JSON nicht kennt',
  'error.json-character': 'Das Zeichen „{char}“ gehört nicht hierher',
  'error.json-trailing': 'Nach dem JSON-Wert folgt weiterer Text',
  'error.json-segments-missing': 'Ein Objekt braucht ein Array „segments“',
  'error.json-grid-integer': '„{key}“ muss eine ganze Zahl von 2 bis {max} sein',
  'error.json-rows-and-cols': 'Geben Sie „rows“ und „cols“ beide an oder keines',
  'error.json-segments-array': '„segments“ muss ein Array sein',
  'error.json-segment-six': 'Eine Strecke braucht 6 Zahlen, diese hat {found}',
  'error.json-number': 'Eine Zahl erwartet',
  'error.json-segment': '[ax, ay, az, bx, by, bz] erwartet',
  'error.json-whole-segments': '{count} Zahlen ergeben keine ganze Zahl von Strecken (je 6)',
  'error.json-grid-count': 'Ein Gitter von {rows} × {cols} braucht {need} Strecken, es sind {found}',
  'error.import-zero-axis': 'Lage {record} hat die Werkzeugachse null (i = j = k = 0) und damit keine Richtung',
  'error.import-too-few-poses': '{found} Lage(n): mindestens 2 sind nötig (eine Werkzeugbahn hat zwei Lagen oder mehr)',
  'error.json-poses-missing': 'Ein Objekt braucht ein Feld „poses“',
  'error.json-poses-array': '„poses“ muss ein Array sein',
  'error.json-pose': 'Eine Lage erwartet: ein Objekt mit "tip": [x, y, z] und "axis": [i, j, k]',
  'error.pose-orientation': 'Lage {pose}: Keine Stellung der Drehachsen von {machine} ergibt diese Werkzeugachse',
  'error.pose-unreachable':
    'Lage {pose} ist nicht erreichbar: {axis} wäre {value}, außerhalb der Grenzen {min} bis {max}',
  'error.linearisation-tolerance':
    'Zwischen den Lagen {pose} und {next} weicht die lineare Interpolation nach {rounds} Runden eingefügter Lagen noch {deviation} mm von der Bahn ab (Toleranz {tolerance} mm): Dort schlagen die Drehachsen um oder gehen durch den Pol',
  'error.flip-in-cut':
    'Zwischen den Lagen {pose} und {next} schlagen die Drehachsen im Schnitt um: {tilt} von {from} auf {to}, während sich die Werkzeugachse um {angle}° dreht, weil {axis} auf derselben Seite {value} erreichen würde, an oder jenseits der Grenzen {min} bis {max}; Grenzen von {axis} erweitern, das Teil drehen oder den Schnitt dort teilen',
  'error.flip-in-cut-free':
    'Zwischen den Lagen {pose} und {next} schlagen die Drehachsen im Schnitt um: {tilt} von {from} auf {to}, während sich die Werkzeugachse um {angle}° dreht; den Schnitt dort teilen',
  'error.retract-horizontal':
    'Lage {pose}: Die Werkzeugachse liegt zu flach, um entlang ihr auf die sichere Höhe zurückzuziehen',
  'error.approach-blocked':
    'Lage {pose}: Kein Punkt auf ihrer Werkzeugachse im Verfahrbereich, von dem das Werkzeug frei vom Rohteil herabfährt (was im Rohteil bleibt oder es aufhält: {part})',
  'error.unwind-blocked':
    'Lage {pose}: Hier muss eine Drehachse zurückdrehen, und kein Punkt der Werkzeugachse im Verfahrbereich lässt sie frei vom Rohteil drehen',
  'error.warn-duplicate-pose': 'Lage {pose} wiederholt Lage {previous}: Für sie wird kein Satz geschrieben',
  'error.warn-flipped-axis':
    'Lage {pose}: Die Werkzeugachse dreht sich um {angle}° gegenüber Lage {previous}; ist sie umgedreht und zeigt von der Spindel weg?',
  'error.warn-slowed':
    '{count} Sätze durch die Grenzen der Achsen verlangsamt, der langsamste mit {feed} {units}/min an der Spitze statt {wanted} ({axis}, Lage {pose})',
  'error.warn-acceleration': '{count} Sätze brauchen noch mehr Beschleunigung, als eine Achse hat, ab Lage {pose}',
  'error.warn-pole-cone':
    '{count} Lagen näher als {cone}° am Pol, ab Lage {pose}: ihre Werkzeugachse um bis zu {angle}° gedreht, damit die Drehachsen ruhig laufen',
  'error.warn-tool-in-stock':
    'Der {part} ragt bei Lage {pose} ins Rohteil ({count} Lagen des Schnitts), um bis zu {depth} {units}',
  'error.csv-pose-numbers':
    '6 Zahlen für eine Lage erwartet (Spitze x, y, z und Werkzeugachse i, j, k), gefunden: {found}',
  'error.csv-pose-angles': 'In jeder der Spalten {columns} eine Zahl erwartet, gefunden: {found} Zahlen',
  'error.pose-angles-machine':
    'Die Lagen geben Drehwinkel ({columns}): Nennen Sie die Maschine dazu (eine Zeile „# machine: <Name>“ oder die gewählte Maschine)',
  'error.pose-header-unknown':
    'Die Kopfzeile {columns} nennt keine Werkzeuglage: Nennen Sie die Spalten der Spitze x, y, z (oder tip_x, tip_y, tip_z) und der Werkzeugachse i, j, k (oder axis_i, axis_j, axis_k; von der Spitze zur Spindel), oder x, y, z und Drehwinkel a, b, c für eine Maschine; ohne Kopfzeile ist jede Zeile Spitze x, y, z und Achse i, j, k',
  'error.pose-angles-letter': 'Die Maschine {machine} hat keine Drehachse {letter}, die die Spalte {letter} angibt',
  'error.target-too-few': '{found} Sollpunkt(e): mindestens 2 sind nötig (eine Sollkurve)',
  'error.target-three-numbers': '3 Zahlen für einen Sollpunkt erwartet (x, y, z), gefunden: {found}',
  'error.target-json': 'Ein Array von Punkten [x, y, z] erwartet, oder ein Objekt mit "points"',
  'error.target-json-point': 'Einen Sollpunkt [x, y, z] erwartet',
  'error.units-unknown':
    'Die Einheit „{said}“ der Datei ist unbekannt: mm oder inch schreiben (auch millimetres, millimeters, in oder inches werden gelesen)',
  'error.part-holder': 'Halter',
  'error.part-shank': 'Schaft',
};
