// Deutsche Texte der Szenen zu Regelflächen (Abschnitte 2–3, eigene Fläche, eigene Daten, große
// Modelle) und die Beschriftungen, die Szenen teilen. Beschriftungen dürfen Indizes wie R_{i,i+1}
// verwenden (ui/richtext.js).
// Keys: param.*, legend.*, readout.*, describe.*, claim.*, surface.*, striction.*, notation.*,
//   convergence.*, isometry.*, formula.*, data.*, large.*

export default {
  'param.surface': 'Fläche',
  'param.rulings': 'Erzeugende N',
  'param.strip': 'Flächenstreifen',
  'param.scheme': 'Schema',
  'param.steps': 'Schritte',

  'legend.rulings': 'Erzeugende R_i',
  'legend.rulings3': 'Erzeugende R_{i−1}, R_i, R_{i+1}',
  'legend.normals': 'gemeinsame Lote N_{i,i+1} mit Fußpunkten',
  'legend.striction': 'Kehlpolygon m_i (dick, mit Punkten)',
  'legend.perpendicularMidpoints': 'Polygon der Lotmittelpunkte (Polygon aus Beispiel 1, gestrichelt)',
  'legend.complexAxis': 'Achse des linearen Komplexes (strichpunktiert)',
  'legend.exactStriction': 'exakte Kehllinie s(u) (breit)',

  'readout.exact': 'exakt',
  'readout.rulings': 'Erzeugende N',
  'readout.parallelPairs': 'parallele Paare',
  'readout.midpointError': 'max |m_i − s(u_i)|',
  'readout.footpointError': 'max |f_{i,i+1} − s(u_i)|',
  'readout.perpendicularMidpointError': 'max |Polygon aus Beispiel 1 − s(u_i + H/2)|',
  'readout.meanDelta': 'δ̄ an der mittleren Erzeugenden',
  'striction.label.meanDelta': 'δ̄ (m_{{i}})',
  'readout.none': 'keine (ein Fehler ist 0 oder nicht definiert)',

  'describe.closed': 'geschlossen',
  'describe.open': 'offen',
  'describe.nothingElse': 'nur die Erzeugenden',

  'claim.title': 'Aussagen des Textes, an der Anzeige geprüft',
  'claim.holds': 'trifft hier zu',
  'claim.fails': 'trifft bei diesen Einstellungen nicht zu',

  'surface.hyperboloid': 'Hyperboloid x² + y²/4 − z²/9 = 1 (Beispiel 1)',
  'surface.quartic': 'Quartische Fläche (1 + vu², u²/2 + uv, u − v) (Beispiel 3)',
  'surface.helicoid': 'Gerade Wendelfläche',
  'surface.helical': 'Schraubregelfläche, Erzeugende unter 45° (von ruledlab, zu Abb. 5)',
  'surface.helical-orthogonal': 'Schraubregelfläche, Erzeugende normal zur Kehlschraublinie (von ruledlab, zu Abb. 5)',
  'surface.pluecker-conoid': 'Plückersches Konoid',
  'surface.hyperbolic-paraboloid': 'Hyperbolisches Paraboloid z = xy',
  'surface.cone': 'Elliptischer Kegel',
  'surface.cylinder': 'Elliptischer Zylinder',
  'surface.helix-tangent': 'Tangentenfläche einer Schraublinie (Torse)',
  'surface.moebius': 'Möbiusband',
  'surface.formula': 'Ihre Fläche',

  'striction.title': 'Kehlpolygon (Abb. 2–3, Beispiel 1)',
  'striction.param.normals': 'Gemeinsame Lote N_{i,i+1}',
  'striction.param.polygon': 'Kehlpolygon m_i',
  'striction.param.midpoints': 'Lotmittelpunkte (Polygon aus Beispiel 1)',
  'striction.param.axis': 'Achse des linearen Komplexes (über die Arbeit hinaus)',
  'striction.param.exact': 'Exakte Kehllinie s(u)',
  'striction.describe':
    'Fläche: {surface}, {closed}, {n} Erzeugende; gezeigt: {shown}. Das Kehlpolygon liegt an den Erzeugenden bis zu {midpoint} von der exakten Kehllinie entfernt; ein einzelner Fußpunkt bis zu {footpoint}. δ̄ an der mittleren Erzeugenden m_{{mid}} beträgt {mean}; das kleinste |δ| eines Paares von Erzeugenden ist {least}.',
  'striction.describe.normals': 'die gemeinsamen Lote mit ihren Fußpunkten',
  'striction.describe.polygon': 'das Kehlpolygon der Fußpunktmittelpunkte',
  'striction.describe.midpoints': 'das Polygon der Lotmittelpunkte',
  'striction.describe.exact': 'die exakte Kehllinie',
  'striction.readout.order.footpoint': 'gemessene Ordnung N → 2N: Fußpunkt',
  'striction.readout.order.midpoint': 'gemessene Ordnung N → 2N: Kehlpolygon m_i',
  'striction.readout.order.perpendicular': 'gemessene Ordnung N → 2N: Polygon aus Beispiel 1',
  'striction.claim.orders':
    'Auf dem Hyperboloid und der Quartik halbiert ab 20 Erzeugenden jede Verdopplung von N den Fehler der Fußpunkte und viertelt die Fehler beider Polygone: gemessene Ordnungen höchstens 0,25 neben 1, 2 und 2.',
  'striction.describeEdited':
    'Ihre Bearbeitung von {n} Erzeugenden von {surface}; gezeigt: {shown}. δ̄ an der mittleren Erzeugenden m_{{mid}} beträgt {mean}; das kleinste |δ| eines Paares von Erzeugenden ist {least}; {parallel:Paar ist:Paare sind} parallel. Ohne die exakte Fläche gibt es keine Fehler zu messen.',

  'notation.title': 'Bezeichnungen: Winkel, Lot, Fußpunkte (Abb. 1)',
  'notation.param.spacing': 'Abstand der Erzeugenden H',
  'notation.param.u': 'Parameter u von R_i',
  'notation.legend.parallel': 'Parallele zu R_{i+1} durch f_{i,i+1} (gestrichelt)',
  'notation.legend.midpoint': 'Mittelpunkt m_i der Fußpunkte auf R_i',
  'notation.readout.angle': 'Winkel φ_{i,i+1} (rad)',
  'notation.readout.distance': 'vorzeichenbehafteter Abstand h_{i,i+1}',
  'notation.readout.delta': 'δ_{i,i+1} = h / φ',
  'notation.describe':
    'Drei aufeinanderfolgende Erzeugende des Hyperboloids aus Beispiel 1, im Parameter {spacing} voneinander entfernt, mit ihren gemeinsamen Loten, Fußpunkten und dem Mittelpunkt m_i; der Winkel zwischen R_i und R_{i+1} ist {angle} rad, ihr vorzeichenbehafteter Abstand h_{i,i+1} beträgt {distance} (sein Betrag ist der Abstand der beiden Geraden), also ist δ_{i,i+1} = h/φ gleich {delta}.',
  'notation.describeEdited':
    'Ihre Bearbeitung dreier aufeinanderfolgender Erzeugender mit ihren gemeinsamen Loten, Fußpunkten und dem Mittelpunkt m_i; der Winkel zwischen R_i und R_{i+1} beträgt {angle} rad, ihr vorzeichenbehafteter Abstand h_{i,i+1} {distance} (sein Betrag ist der Abstand der beiden Geraden), also ist δ_{i,i+1} = h/φ gleich {delta}.',

  'convergence.title': 'Konvergenzordnungen (Sätze 1–2)',
  'convergence.param.u': 'Parameter u',
  'convergence.param.h0': 'Größter Schritt H₀',
  'convergence.param.levels': 'Halbierungen',
  'convergence.legend.rulings': 'R(u − H), R(u), R(u + H) für das größte H',
  'convergence.legend.midpoint': 'Mittelpunkt m_i der Fußpunkte auf R(u)',
  'convergence.legend.tangent': 'Zentraltangente s(u) + [e_3(u)] (4) (gestrichelt)',
  'convergence.series.footpoint': 'Fußpunkt f_{i,i+1} (Ordnung {order})',
  'convergence.series.midpoint': 'Mittelpunkt m_i (Ordnung {order})',
  'convergence.series.distribution': 'δ_{i,i+1} (Ordnung {order})',
  'convergence.series.distributionMean': 'gemitteltes δ̄_i (Ordnung {order})',
  'convergence.series.centralNormal': 'gemeinsames Lot (Ordnung {order})',
  'convergence.plot.x': 'Schritt H',
  'convergence.plot.y': 'Fehler',
  'convergence.plot.title': 'Fehler der diskreten Invarianten gegen den Schritt H (doppeltlogarithmisch)',
  'convergence.plot.slope': 'Steigung {k}',
  'convergence.readout.footpoint': 'Ordnung von f_{i,i+1}',
  'convergence.readout.midpoint': 'Ordnung des Mittelpunkts m_i',
  'convergence.readout.delta': 'Ordnung von δ_{i,i+1}',
  'convergence.readout.deltaMean': 'Ordnung des gemittelten δ̄_i',
  'convergence.readout.normal': 'Ordnung von N_{i,i+1} → Zentraltangente',
  'convergence.describe':
    'Fehler der diskreten Invarianten bei u = {u}, für Schritte ab {h0} über {levels} Halbierungen: Der Fußpunkt konvergiert mit Ordnung {footpoint}, der Mittelpunkt der Fußpunkte mit Ordnung {midpoint}.',
  'convergence.describeEdited':
    'Ihre Bearbeitung der drei Erzeugenden mit ihren gemeinsamen Loten, Fußpunkten und dem Kehlpunkt; der gemittelte Drall an der mittleren Erzeugenden ist {delta}.',
  'convergence.editedNote':
    'Die Ordnungen werden an der exakten Fläche gemessen, die Ihre Bearbeitung nicht hat: „Zurück zur eingebauten Eingabe“ misst sie wieder.',
  'convergence.readout.delta01': 'δ_{0,1}',
  'convergence.readout.delta12': 'δ_{1,2}',
  'convergence.readout.deltaMeanEdited': 'gemitteltes δ an der mittleren Erzeugenden',

  'isometry.title': 'Isometrische Verbiegung und Abwicklung (Abb. 4–6)',
  'isometry.param.layout': 'Ansicht',
  'isometry.layout.bend': 'Verbiegen zum konoidalen Modell',
  'isometry.layout.panels': 'Drei Felder: Fläche | konoidal | Abwicklung (Abb. 6)',
  'isometry.param.t': 'Verbiegung t',
  'isometry.param.ghost': 'Ursprüngliche Fläche (blass)',
  'isometry.reason.panels': 'Die Ansicht mit drei Feldern zeigt immer t = 1.',
  'isometry.reason.flat': 'Bei t = 0 ist die Fläche die ursprüngliche.',
  'isometry.legend.striction': 'Kehlpolygon (in der Abwicklung: sein Bild)',
  'isometry.legend.envelope':
    'in der Abwicklung: das von den Erzeugenden eingehüllte Polygon, Bild des Polygons aus Beispiel 1 (gestrichelt)',
  'isometry.legend.ghost': 'ursprüngliche Fläche (gestrichelt)',
  'isometry.readout.nonDevelopability': 'Nichtabwickelbarkeit (Höhe des konoidalen Modells)',
  'isometry.readout.isometry': 'max. relative Änderung einer Kantenlänge',
  'isometry.describe':
    '{surface} als {n} Erzeugende, isometrisch verbogen bis t = {t} zum konoidalen Modell; das konoidale Modell ist {height} hoch.',
  'isometry.describe.cone.one':
    'Erzeugende {i} trifft keine ihrer Nachbarinnen (bis zu {distance} entfernt); jedes andere Paar aufeinanderfolgender Erzeugender trifft sich, wie auf einem Kegel.',
  'isometry.describe.cone.some':
    'Die Erzeugenden {list} treffen keine ihrer Nachbarinnen (bis zu {distance} entfernt); jedes andere Paar aufeinanderfolgender Erzeugender trifft sich.',
  'isometry.describe.cone.pairs':
    'Die aufeinanderfolgenden Erzeugenden {list} treffen sich nicht (bis zu {distance} entfernt).',
  'isometry.describe.cone.all': 'Jedes Paar aufeinanderfolgender Erzeugender trifft sich, wie auf einem Kegel.',
  'isometry.describePanels':
    '{surface} als {n} Erzeugende (links), ihr konoidales Modell (Mitte) und ihre Näherungsabwicklung (rechts); das konoidale Modell ist {height} hoch.',
  'isometry.download.development': 'Abwicklung herunterladen (SVG)',
  'isometry.download.title': 'Näherungsabwicklung (ruledlab)',
  'isometry.readout.radius': 'ρ, Krümmungsradius der Hüllkurve der abgewickelten Erzeugenden (mittlere Erzeugende)',
  'isometry.readout.radiusFiner': 'ρ mit 2N − 1 Erzeugenden',
  'isometry.claim.helical':
    'Die Bildunterschrift von Abb. 5 trifft hier nicht zu: ab 6 Erzeugenden liegt ρ höchstens 0,1 neben r + p tan β = 1,4; die konoidalen Erzeugenden berühren einen Zylinder mit diesem Radius und verfehlen die Achse.',
  'isometry.claim.orthogonal':
    'Hier trifft die Bildunterschrift im Grenzwert zu: ρ geht mit zweiter Ordnung gegen 0 (bei doppelt so vielen Erzeugenden auf ein Drittel bis ein Fünftel).',
  'isometry.readout.delta': 'δ des mittleren Paares von Erzeugenden',

  'formula.title': 'Ihre Fläche (Formeln)',
  'formula.param.preset': 'Ausgehend von',
  'formula.param.umin': 'u von',
  'formula.param.umax': 'u bis',
  'formula.param.vmin': 'v von',
  'formula.param.vmax': 'v bis',
  'formula.param.closed': 'In u geschlossen',
  'formula.param.a': 'Parameter a',
  'formula.param.b': 'Parameter b',
  'formula.param.c': 'Parameter c',
  'formula.param.tool': 'Werkzeug',
  'formula.tool.striction': 'Kehlpolygon (Abschnitt 2)',
  'formula.tool.convergence': 'Konvergenzordnungen (Sätze 1–2)',
  'formula.tool.bending': 'Verbiegung zum konoidalen Modell (Abschnitt 3)',
  'formula.tool.development': 'Näherungsabwicklung (Abb. 6)',
  'formula.tool.subdivision': 'Unterteilung (Abschnitt 4)',
  'formula.reason.tool': 'Vom gewählten Werkzeug nicht verwendet.',
  'formula.problem.notClosed':
    '„In u geschlossen“ lässt auf die letzte Erzeugende die erste folgen, aber diese Fläche schließt sich nicht: Ihre Erzeugende bei u = {umax} ist nicht die bei u = {umin} ({gap} entfernt, unter {angle} rad). Nehmen Sie das Häkchen für eine Fläche heraus, die sich nicht schließt.',
  'formula.scheme.fourPoint': 'Vierpunktschema w = 1/16',
  'formula.scheme.chaikin': 'Chaikin',
  'formula.scheme.variational': 'Variationell (gekoppelt)',
  'formula.scheme.lines': 'Vierpunktschema im Geradenraum',
  'formula.legend.given': 'abgetastete Erzeugende',
  'formula.legend.inserted': 'eingefügte Erzeugende',
  'formula.describeSubdivision':
    'Ihre Fläche als {n} Erzeugende, verfeinert mit {steps:Schritt:Schritten} zu {total} Erzeugenden; die eingefügten liegen höchstens {distance} von der exakten Fläche entfernt.',
  // Feldnamen in Meldungen: „z-Komponente von e(u)“, das Feld „u von“
  'formula.param.ax.field': 'x-Komponente von a(u)',
  'formula.param.ay.field': 'y-Komponente von a(u)',
  'formula.param.az.field': 'z-Komponente von a(u)',
  'formula.param.ex.field': 'x-Komponente von e(u)',
  'formula.param.ey.field': 'y-Komponente von e(u)',
  'formula.param.ez.field': 'z-Komponente von e(u)',
  'formula.param.umin.field': 'das Feld „u von“',
  'formula.param.umax.field': 'das Feld „u bis“',
  'formula.param.vmin.field': 'das Feld „v von“',
  'formula.param.vmax.field': 'das Feld „v bis“',

  'data.title': 'Ihre Daten',
  'data.param.closed': 'Geschlossen (auf die letzte Erzeugende folgt die erste)',
  'data.legend.rulings': 'Ihre Erzeugenden',
  'data.legend.strictionDetail': 'Kehllinie (durch die gezeichneten Erzeugenden)',
  'data.note.closedGrid':
    '„Geschlossen“ lässt auf die letzte Erzeugende einer Fläche die erste folgen; ein Raster von Geraden wird gezeigt, wie es ist, nicht geschlossen.',
  'data.note.detail':
    'Detailstufe: Streifen und Kehllinie gehen durch jede {every}. Erzeugende ({drawn} davon), und jede {lines}. wird als Gerade gezeichnet; die Zahlen gelten für alle Erzeugenden. Ziehen lassen sich Erzeugende in Modellen mit bis zu {max}.',
  'data.note.computing':
    'Die Invarianten aller {n} Erzeugenden werden im Hintergrund berechnet („Abbrechen“ beendet die Berechnung).',
  'data.note.cancelled':
    'Die Invarianten der {n} Erzeugenden wurden nicht berechnet (abgebrochen): Ändern Sie eine Einstellung, um sie zu berechnen.',
  'data.note.focalRulings':
    'Brennflächen hat ein Raster von Geraden; Ihre Erzeugenden sind eine Fläche, die keine hat.',
  'data.readout.lines': 'Geraden (Kongruenz)',
  'data.describe':
    'Ihre Regelfläche aus {n} Erzeugenden ({parallel} parallele Paare) mit ihren gemeinsamen Loten und ihrem Kehlpolygon; das kleinste |δ| eines Paares von Erzeugenden ist {least}.',
  'data.describeDetail':
    'Ihre Regelfläche aus {n} Erzeugenden ({parallel} parallele Paare), in einer Detailstufe gezeichnet, mit ihrer Kehllinie; das kleinste |δ| eines Paares von Erzeugenden ist {least}.',
  'data.describeCancelled':
    'Ihre Regelfläche aus {n} Erzeugenden; ihre Invarianten wurden nicht berechnet (abgebrochen).',
  'data.describePending': 'Ihre Regelfläche aus {n} Erzeugenden; ihre Invarianten werden berechnet.',
  'data.describeCongruence': 'Ihre Geradenkongruenz aus {rows} × {cols} Geraden.',

  'large.title': 'Große Modelle in einem Web Worker',
  'large.param.steps': 'Schritte des Vierpunktschemas',
  'large.param.rulings': 'Erzeugende als Linien',
  'large.legend.strip': 'Streifen der Wendelfläche',
  'large.readout.rulings': 'Erzeugende des Modells',
  'large.readout.drawn': 'Erzeugende im gezeichneten Streifen',
  'large.readout.lines': 'als Linien gezeichnete Erzeugende',
  'large.note.lod': 'Detailstufe: Der Streifen wird durch jede {every}. Erzeugende gezeichnet ({drawn} davon).',
  'large.note.lines':
    'Jede {every}. Erzeugende wird als Linie gezeichnet, damit die Linien auf dem Bildschirm getrennt bleiben.',
  'large.describe': 'Eine Wendelfläche mit {rulings} Erzeugenden, davon {drawn} gezeichnet.',
};
