// Deutsche Texte der Szene zur Klein-Quadrik (über die Arbeit hinaus): Geraden als Punkte des P⁵.
// Keys: klein.*
import { sub, m, mr, display, row } from '../mathml.js';

const L1 = sub('L', '1');
const L2 = sub('L', '2');
/** Ω(L₁, L₂) = 𝐝₁ · 𝐦₂ + 𝐝₂ · 𝐦₁ */
const omega = `<mi>Ω</mi><mo>(</mo>${L1}<mo>,</mo>${L2}<mo>)</mo><mo>=</mo>${sub('𝐝', '1')}<mo>·</mo>${sub('𝐦', '2')}<mo>+</mo>${sub('𝐝', '2')}<mo>·</mo>${sub('𝐦', '1')}`;
/** Ω(L_i, L_{i+1}) = −h_{i,i+1} sin φ_{i,i+1} */
const relation = `<mi>Ω</mi><mo>(</mo>${sub('L', 'i')}<mo>,</mo>${sub('L', 'i + 1')}<mo>)</mo><mo>=</mo><mo>−</mo>${sub('h', 'i , i + 1')}${row('sin')}${sub('φ', 'i , i + 1')}`;

export default {
  'klein.title': 'Die Klein-Quadrik: Geraden als Punkte (über die Arbeit hinaus)',
  'klein.param.mix': 'Mischung α der beiden Sphären (°)',
  'klein.param.turn': 'Drehung β der zweiten Sphäre (°)',
  'klein.param.unit': 'Längeneinheit ℓ',
  'klein.param.conic': 'Kegelschnitt der Ebene der ersten, mittleren und letzten Geraden',
  'klein.param.space': 'Die Geraden im Raum, daneben',
  'klein.param.mark':
    'Markierte Gerade i: eine Erzeugende R_i oder eine Gerade des Gitters, Zeile für Zeile (fett im Raum, rot auf M)',
  'klein.param.source': 'Fläche oder Kongruenz',
  'klein.legend.points': 'Erzeugende R_i als Punkte von M',
  'klein.legend.positive': 'Schritt mit Ω(L_i, L_{i+1}) > 0',
  'klein.legend.negative': 'Schritt mit Ω < 0 (gestrichelt)',
  'klein.legend.torsal': 'torsaler Schritt: Ω = 0, die Erzeugenden schneiden sich oder sind parallel',
  'klein.legend.outline': 'das Bild von M: die begrenzenden Sphären',
  'klein.legend.conic': 'Kegelschnitt: die Ebene dreier Erzeugender auf M',
  'klein.legend.gridPoints': 'die Geraden der Kongruenz als Punkte von M',
  'klein.legend.gridPositive': 'Kante des Netzes mit Ω > 0',
  'klein.legend.gridNegative': 'Kante mit Ω < 0 (gestrichelt)',
  'klein.legend.gridTorsal': 'torsale Kante: Ω = 0, die benachbarten Geraden schneiden sich oder sind parallel',
  'klein.readout.gridTorsal': 'torsale Kanten des Netzes (Ω = 0)',
  'klein.readout.gridMarked': 'Ω der markierten Geraden und der nächsten ihrer Zeile',
  'klein.readout.gridNoStep': 'die letzte Gerade ihrer Zeile: keine nächste',
  'klein.describe.grid':
    'Die {n} × {n} Geraden der Kongruenz „{surface}“ als Punkte der Klein-Quadrik M, gezeichnet mit α = {mix}°, β = {turn}°, ℓ = {unit}: Das Bild von M ist die Schale zwischen den Sphären mit den Radien {inner} und {outer} um die Mitte, gezeichnet als graue Kreise. Die Punkte bilden ein Netz: Jeder ist mit der nächsten Geraden seiner Zeile und seiner Spalte verbunden; torsale Kanten (Ω = 0: die beiden Geraden schneiden sich oder sind parallel): {torsal} von {steps}; das kleinste |Ω| liegt auf der Kante zwischen den Geraden {least} des Gitters (Zeile, Spalte): Ω = {omega}. Das größte Klein-Residuum ist {residual}.',
  'klein.describe.gridMark':
    'Die Gerade {i} des Gitters (Zeile {row}, Spalte {col}) ist markiert: fett im Raum, ein roter Punkt auf M.',
  'klein.param.side': 'Geraden je Seite des Gitters der Kongruenz',
  'klein.reason.congruence': 'Das Gitter einer Kongruenz hat einen eigenen Regler: Geraden je Seite.',
  'klein.reason.surface': 'Nur eine Kongruenz hat ein Gitter.',
  'klein.pane.label': 'Klein-Ansicht: die Geraden der Szene als Punkte der Klein-Quadrik M',
  'klein.pane.canvas': 'Die Klein-Quadrik',
  'klein.pane.none':
    'Dieses Bild hat keine eigenen Geraden zum Herunterladen und darum keine, die auf der Klein-Quadrik zu zeigen wären. Die Szenen, deren Geraden man als Daten herunterladen kann, zeigen sie hier.',
  'klein.pane.tooMany': '{count} Geraden: mehr, als die Klein-Ansicht zeichnet ({max}).',
  'klein.pane.marked': 'Gerade {i} von {count} ist markiert: fett im Raum, auf M umkreist.',
  'klein.pane.failed': 'Die Klein-Ansicht kann diese Geraden nicht zeichnen: {message}',
  'klein.pane.steer': 'Das Bild des P⁵ in der Klein-Ansicht',
  'klein.pane.steerShort': 'Bild α, β, ℓ',
  'klein.pane.mix': 'α',
  'klein.pane.turn': 'β',
  'klein.pane.unit': 'ℓ',
  'klein.pane.slider': 'Klein-Ansicht: {name}',
  'klein.pane.describe':
    'Daneben die Klein-Ansicht: die {count} Geraden der Szene als Punkte der Klein-Quadrik M, der Reihe nach verbunden (α = {mix}°, β = {turn}°, ℓ = {unit}). Torsale Schritte (Ω = 0: aufeinanderfolgende Geraden schneiden sich): {torsal} von {steps}; das kleinste |Ω| ist {least}. Das größte Klein-Residuum ist {residual}; der bestpassende lineare Komplex verfehlt die Geraden um {complex}.',
  'klein.pane.describeGrid':
    'Daneben die Klein-Ansicht: die {rows} × {cols} Geraden des Gitters als Punkte der Klein-Quadrik M, ein Netz, dessen Kanten benachbarte Geraden einer Zeile und einer Spalte verbinden (α = {mix}°, β = {turn}°, ℓ = {unit}). Torsale Kanten (Ω = 0: die beiden Geraden schneiden sich): {torsal} von {steps}; das kleinste |Ω| ist {least}. Das größte Klein-Residuum ist {residual}; der bestpassende lineare Komplex verfehlt die Geraden um {complex}.',
  'klein.legend.gridConic': 'Kegelschnitt: die Ebene der ersten, mittleren und letzten Geraden auf M',
  'klein.readout.gridLeast': 'Ω an der Kante mit dem kleinsten |Ω|',
  'klein.readout.gridPlane': 'größter Abstand einer Geraden von der Ebene des Kegelschnitts',
  'klein.readout.gridNoPlane': 'die drei Geraden spannen keinen Kegelschnitt auf',
  'klein.describe.gridConic':
    'Der Kegelschnitt, in dem die Ebene der ersten, mittleren und letzten Geraden M schneidet, ist hellblau gezeichnet; die Geraden liegen höchstens {plane} von dieser Ebene entfernt.',
  'klein.describe.gridNoConic':
    'Die erste, mittlere und letzte Gerade spannen keine Ebene auf, die M in einem Kegelschnitt schneidet.',
  'klein.readout.residual': 'größtes Klein-Residuum |Ω(L, L)|/2',
  'klein.readout.torsal': 'torsale Schritte (Ω = 0)',
  'klein.readout.least': 'Ω am Schritt mit kleinstem |Ω|',
  'klein.readout.marked': 'Ω(L_i, L_{i+1}) der markierten Erzeugenden',
  'klein.readout.noStep': 'die letzte Erzeugende: keine nächste',
  'klein.readout.plane': 'größter Abstand einer Erzeugenden von der Ebene des Kegelschnitts',
  'klein.readout.noPlane': 'die drei Erzeugenden spannen keinen Kegelschnitt auf',
  'klein.readout.complex': 'größtes |Ω(C, L_i)| für den bestpassenden linearen Komplex C',
  'klein.readout.congruence':
    'Residuum des zweitbesten linearen Komplexes (0: die Geraden liegen in einer linearen Kongruenz, einem Schnitt von M mit einem 3-Raum)',
  'klein.describe':
    'Die {n} Erzeugenden der Fläche „{surface}“ als Punkte der Klein-Quadrik M, gezeichnet mit α = {mix}°, β = {turn}°, ℓ = {unit}: Das Bild von M ist die Schale zwischen den Sphären mit den Radien {inner} und {outer} um die Mitte, gezeichnet als graue Kreise. Die Punkte sind der Reihe nach verbunden; {torsal} der {steps} Schritte sind torsal (Ω = 0), das kleinste |Ω| liegt bei Schritt {least}: Ω = {omega}. Das größte Klein-Residuum ist {residual}.',
  'klein.describe.mark': 'Die Erzeugende R_{i} ist markiert: fett im Raum, ein roter Punkt auf M.',
  'klein.describe.conic':
    'Der Kegelschnitt, in dem die Ebene der ersten, mittleren und letzten Erzeugenden M schneidet, ist hellblau gezeichnet; die Erzeugenden liegen höchstens {plane} von dieser Ebene entfernt.',
  'klein.describe.noConic':
    'Die erste, mittlere und letzte Erzeugende spannen keine Ebene auf, die M in einem Kegelschnitt schneidet.',
  'klein.describe.space':
    'Links von M, wie die Szene sie zuerst zeigt, die Geraden im Raum, um die Mitte ihres Quaders skaliert; die Erzeugenden einer Fläche sind dort Griffe (Bearbeiten).',
  'klein.text': `
<p>Eine Gerade des Raums ist ein Punkt einer Quadrik in einem fünfdimensionalen projektiven Raum: Eine
orientierte Gerade mit dem Einheitsvektor ${m('<mi>𝐝</mi>')} als Richtung durch einen Punkt ${m('<mi>𝐩</mi>')}
hat die Plücker-Koordinaten ${mr('( 𝐝 , 𝐦 )')}, ${mr('𝐦 = 𝐩 × 𝐝')}, und jedes solche Paar erfüllt
${mr('𝐝 · 𝐦 = 0')}: die Klein-Quadrik M. Die Klein-Form ${m(omega)} verschwindet genau dann, wenn sich
die beiden Geraden schneiden oder parallel sind.</p>
${display(relation, 'K7')}
<p>Für aufeinanderfolgende Erzeugende ist sie der negative vorzeichenbehaftete Abstand mal dem Sinus des
Winkels, mit den Vorzeichen von Abschnitt 2: null an einem torsalen Schritt, an dem sich die Erzeugenden
schneiden (jeder Schritt eines Kegels oder einer Tangentenfläche), sonst mit dem Vorzeichen von −δ. Das
Polygon der Punkte der Erzeugenden ist danach gefärbt.</p>
<p>M ist vierdimensional; kein Bild zeigt die Quadrik ganz. Hier werden die Koordinaten mit einer
Längeneinheit ℓ in zwei Vektoren ${mr('𝐱 = ( 𝐝 + 𝐦 / ℓ ) / s')} und ${mr('𝐲 = ( 𝐝 − 𝐦 / ℓ ) / s')}
zerlegt, die genau auf M Einheitsvektoren sind: M ist ein Paar von Sphären, und zwei Geraden schneiden
sich, wenn ihre Punkte auf der ersten Sphäre ebenso weit voneinander entfernt sind wie auf der zweiten.
Die Ansicht zeichnet ${mr('cos α 𝐱 + sin α 𝐲')} (die zweite Sphäre um β um die Hochachse gedreht):
α = 0 zeigt die erste Sphäre, 90° die zweite, 45° die Richtung der Geraden, umso näher an der Mitte, je
weiter die Gerade am Ursprung vorbeigeht. Das Bild ist linear: Die Sehne zweier Punkte ist eine Gerade
des projektiven Raums, die genau an torsalen Schritten auf M liegt.</p>
<p>Die Erzeugenden des Hyperboloids bilden eine Regelschar: Die Ebene, die drei von ihnen aufspannen,
schneidet M in einem Kegelschnitt, der durch alle hindurchgeht. Die Erzeugenden der Schraubflächen
liegen in einem linearen Komplex, einem Hyperebenenschnitt von M: Die Anzeige gibt an, wie weit ihre
Punkte von der Hyperebene des bestpassenden linearen Komplexes entfernt sind.</p>`,
};
