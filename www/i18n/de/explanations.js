// Deutsche Erläuterungen der Szenen: Markup (HTML mit MathML) aus den eigenen Dateien des Projekts.
// Keys: striction.text, notation.text, convergence.text, isometry.text, curves.text, strip.text,
//   congruence.text, milling.text, formula.text, focal.text, formulaCongruence.text, lines.text,
//   large.text, data.text
// Die Grenzen der Seite werden aus limits.js zitiert, nie abgeschrieben.
import { sub, m, mr, display, frac, row, fii1, fiim, Ri, grouped } from '../mathml.js';
import { DRAW_LIMIT, MAX_LINK_RULINGS, TURNING_FROM, TURNING_STEPS } from '../../limits.js';

export default {
  'striction.text': `
<h2>Differenzengeometrie einer Regelfläche</h2>
<p>Eine diskrete Regelfläche ist eine Folge von Geraden ${m(Ri)}. Zwei aufeinanderfolgende
Erzeugende schließen den Winkel ${m(sub('φ', 'i , i + 1'))} ein und haben genau ein gemeinsames Lot
${m(sub('N', 'i , i + 1'))}. Es trifft ${m(Ri)} im Fußpunkt ${m(fii1)}; die beiden Fußpunkte eines
Paares haben den Abstand ${m(`<mo>|</mo>${sub('h', 'i , i + 1')}<mo>|</mo>`)}: ${m(sub('h', 'i , i + 1'))} ist ihr vorzeichenbehafteter Abstand,
dessen Vorzeichen den Windungssinn (Schraubsinn) des Paares angibt. Der <em>diskrete Drall</em> (Verteilungsparameter) ist</p>
${display(`${sub('δ', 'i , i + 1')}<mo>=</mo>${frac(sub('h', 'i , i + 1'), sub('φ', 'i , i + 1'))}`, '1')}
<p>Jede Erzeugende trägt zwei Fußpunkte, ${m(fiim)} und ${m(fii1)}. Beide streben gegen den
<em>Kehlpunkt</em> ${mr('s ( u )')}, wenn die Erzeugenden zusammenrücken, aber nur von erster Ordnung
(Satz 1). Ihr Mittelpunkt</p>
${display(`${sub('m', 'i')}<mo>=</mo>${frac('<mn>1</mn>', '<mn>2</mn>')}<mo>(</mo>${fiim}<mo>+</mo>${fii1}<mo>)</mo>`, '7')}
<p>konvergiert von zweiter Ordnung (Satz 2): Die Fehler erster Ordnung der beiden Fußpunkte sind
gleich groß und entgegengesetzt. Das <em>Kehlpolygon</em> verbindet diese Mittelpunkte.</p>
<p><strong>Zwei Polygone, nicht eines.</strong> Wörtlich gelesen beschreibt Beispiel 1 ein anderes Polygon: die
Mittelpunkte ${m(`<mo>(</mo>${fii1}<mo>+</mo>${sub('f', 'i + 1 , i')}<mo>)</mo><mo>/</mo><mn>2</mn>`)} der
gemeinsamen Lote (zuschaltbar). Es nähert die Kehllinie (Striktionslinie) beim Parameter <em>zwischen</em> zwei
Erzeugenden an, ${mr('u + H / 2')}, ebenfalls von zweiter Ordnung; das Kehlpolygon
${m(sub('m', 'i'))} nähert sie an den Erzeugenden selbst an. Die Anzeige misst beide.</p>
<p><strong>Probieren Sie es aus.</strong> Verdoppeln Sie die Zahl der Erzeugenden und beobachten Sie
die Anzeige: Der Fehler der Fußpunkte halbiert sich, die Fehler beider Polygone fallen auf ein
Viertel (auf dem Hyperboloid und der Quartik ab etwa 20 Erzeugenden; die Anzeige misst die Ordnungen
von N zu 2N Erzeugenden). Beim Hyperboloid aus Beispiel 1 ist die Kehllinie nicht die Kehlellipse; beim Kegel
treffen sich alle gemeinsamen Lote in der Spitze; beim Zylinder sind aufeinanderfolgende Erzeugende
parallel, das gemeinsame Lot ist nicht eindeutig, und ruledlab sagt das (kein Wert, das Paar als
parallel gezählt), statt zu raten.</p>
<p class="rl-paper-data">Daten: Das Hyperboloid x² + y²/4 − z²/9 = 1 aus Beispiel 1 stammt aus der
Arbeit; die Zahl der Erzeugenden (36) und die Länge der Strecken wählt ruledlab.</p>`,

  'notation.text': `
<h2>Abb. 1: die Bezeichnungen</h2>
<p>Drei aufeinanderfolgende Erzeugende ${m(sub('R', 'i − 1'))}, ${m(Ri)}, ${m(sub('R', 'i + 1'))} des
Hyperboloids aus Beispiel 1. Jedes Paar hat genau ein gemeinsames Lot ${m(sub('N', 'i , i + 1'))}; es
trifft ${m(Ri)} im Fußpunkt ${m(fii1)} und ${m(sub('R', 'i + 1'))} in ${m(sub('f', 'i + 1 , i'))}.
Seine Länge ist der Abstand der beiden Erzeugenden; mit Vorzeichen (nach dem Windungssinn, dem
Schraubsinn, des Paares) ist sie der vorzeichenbehaftete Abstand ${m(sub('h', 'i , i + 1'))} der Anzeige. Die gestrichelte Gerade durch ${m(fii1)} ist parallel zu
${m(sub('R', 'i + 1'))}: Sie schließt mit ${m(Ri)} den Winkel ${m(sub('φ', 'i , i + 1'))} ein. Jede
Erzeugende trägt zwei Fußpunkte, einen von jedem Nachbarn; ihr Mittelpunkt ${m(sub('m', 'i'))} ist der
diskrete Kehlpunkt. Verkleinern Sie den Abstand und sehen Sie, wie die beiden Fußpunkte auf ihn
zurücken.</p>`,

  'convergence.text': `
<h2>Wie schnell die diskreten Invarianten konvergieren</h2>
<p>Nehmen Sie die Erzeugenden ${mr('R ( u − H )')}, ${mr('R ( u )')}, ${mr('R ( u + H )')} einer
analytischen Fläche und verkleinern Sie H. Satz 1: Der Fußpunkt ${m(fii1)} strebt gegen den Kehlpunkt
${mr('s ( u )')} und ${m(`${sub('δ', 'i , i + 1')}<mo>=</mo>${row('h / φ')}`)} gegen den Drall, beide
mit Fehlern proportional zu H (Steigung 1 im Diagramm), und das gemeinsame Lot strebt gegen die
<em>Zentraltangente</em> durch ${mr('s ( u )')}:</p>
${display(`${mr('s ( u ) +')}<mo>[</mo>${sub('e', '3')}${mr('( u )')}<mo>]</mo><mo>=</mo><munder><mo>lim</mo>${row('h → 0')}</munder>${sub('N', 'i , i + 1')}`, '4')}
<p>(die gestrichelte Gerade in der Ansicht). Satz 2: Der Mittelpunkt der beiden Fußpunkte auf
${mr('R ( u )')} und das Mittel der beiden δ sind viel besser: Ihre Fehler erster Ordnung heben sich
auf, übrig bleiben Fehler proportional zu ${m('<msup><mi>H</mi><mn>2</mn></msup>')} (Steigung 2). Das
Diagramm ist vom Kern gemessen, nicht aus den Formeln gezeichnet.</p>
<p>Versuchen Sie die Schraubregelfläche: Dort liegen die beiden Fußpunkte genau symmetrisch zu
${mr('s ( u )')}, der Mittelpunkt ist exakt (die Anzeige sagt „exakt“), und δ ist von zweiter Ordnung,
weil das diskrete δ eine gerade Funktion von H ist. Beim Plückerschen Konoid liegen die Fußpunkte
genau auf der Achse.</p>`,

  'isometry.text': `
<h2>Eine Regelfläche verbiegen, ohne sie zu dehnen</h2>
<p>Fassen Sie zwei aufeinanderfolgende Erzeugende ${m(Ri)}, ${m(sub('R', 'i + 1'))} samt ihrem
gemeinsamen Lot zu einem starren Körper zusammen, und lassen Sie jede Erzeugende als <em>Gelenk</em>
zwischen den beiden Körpern wirken, zu denen sie gehört. Drehungen um die Gelenke bewegen die
Erzeugenden, aber kein Polygon ${m(`${sub('p', 'i')}<mo>∈</mo>${Ri}`)} ändert die Länge einer Kante:
Diese kinematische Kette ist das diskrete Modell der <em>Mindingschen Isometrien</em>, die Erzeugende
auf Erzeugende abbilden. Die Anzeige zeigt die größte relative Längenänderung einer Kante: Rundung,
sonst nichts.</p>
<p><strong>Beispiel 2.</strong> Halten Sie ${m(sub('R', '0'))} und ${m(sub('R', '1'))} fest und drehen
Sie jeden folgenden Körper um sein Gelenk, bis sein gemeinsames Lot dieselbe Richtung hat wie das
erste, ${m(sub('n', '0 , 1'))}. Dann steht jede Erzeugende normal zu dieser Richtung: Die Fläche ist
<em>konoidal</em> geworden (alle Erzeugenden parallel zu einer Ebene). Schieben Sie <em>t</em> von 0
bis 1 (oder drücken Sie Abspielen), um die Verbiegung zu sehen; das Bild ist so gedreht, dass
${m(sub('n', '0 , 1'))} nach oben zeigt, und die konoidalen Erzeugenden werden waagrecht, gestapelt in
den Höhen ${m(`${sub('ζ', 'i')}<mo>=</mo><munder><mo>∑</mo>${row('k < i')}</munder>${sub('h', 'k , k + 1')}`)}.</p>
<p><strong>Näherungsabwicklung (Abb. 6).</strong> Projizieren Sie das konoidale Modell normal auf eine
Ebene parallel zu seinen Erzeugenden. Jede Erzeugende behält ihre Länge. Die gemeinsamen Lote des
konoidalen Modells zeigen alle in dieselbe Richtung, die beiden Fußpunkte jedes Paares fallen also in einen Punkt,
den Schnittpunkt der beiden projizierten Erzeugenden: Diese Punkte bilden das Polygon, das die
projizierten Erzeugenden einhüllen (gestrichelt; das Bild des Polygons der Lotmittelpunkte aus
Beispiel 1), so wie die Gratlinie in der Abwicklung einer Torse die Einhüllende ist. Das Bild des
Kehlpolygons ist diesem Polygon eingeschrieben: ${m(sub('m', 'i'))} liegt in der Mitte zwischen den
beiden Fußpunkten auf ${m(Ri)}, sein Bild also im Mittelpunkt der Kante, die auf dieser Erzeugenden
liegt. Die Spanne der Höhen,
${m(`<mo>max</mo>${sub('ζ', 'i')}<mo>−</mo><mo>min</mo>${sub('ζ', 'i')}`)}, misst, wie weit die Fläche
von einer Torse entfernt ist: 0 beim Kegel, winzig (und mit ${m('<msup><mi>H</mi><mn>2</mn></msup>')}
fallend) bei der Tangentenfläche, deutlich positiv beim Hyperboloidstreifen.</p>
<p class="rl-beyond"><strong>Über die Arbeit hinaus: wann die Bildunterschrift von Abb. 5 stimmt.</strong>
Die Arbeit zeigt das konoidale Bild einer Schraubregelfläche als Wendelfläche, deren Erzeugende die
Achse senkrecht treffen. Hier gemessen gilt das nur, wenn die Kehllinie die Erzeugenden rechtwinklig
kreuzt. Im Allgemeinen berühren die konoidalen Erzeugenden einen Zylinder um die Achse mit dem Radius
${m(frac(row('e · ṡ'), row('| e′ |')))}: 1,4 für die Fläche mit Erzeugenden unter 45° (Radius 1,
Schraubparameter 0,4, also Höhe 0,4 je Radiant: z = 0,4 u). Die Anzeige misst ihn diskret: ρ, die (vorzeichenbehaftete) Differenz der beiden Fußpunkte auf einer
Erzeugenden geteilt durch den Winkel, um den sich die Erzeugenden dort drehen, ist der Krümmungsradius
der Hüllkurve der abgewickelten Erzeugenden und strebt mit zweiter Ordnung gegen
${m(frac(row('e · ṡ'), row('| e′ |')))}. Wählen Sie „Erzeugende normal zur Kehlschraublinie“
(β = −atan(r/p)), dann strebt ρ gegen 0: Im Grenzwert erscheint die Wendelfläche der Bildunterschrift.</p>
<p class="rl-paper-data">Die Arbeit gibt für Abb. 4–6 keine Daten an; ruledlab verwendet die
Quartik aus Beispiel 3, eine Schraubregelfläche (Radius 1, Schraubparameter 0,4 je Radiant, also Ganghöhe 2π · 0,4 ≈ 2,51) und einen Streifen des
Hyperboloids aus Beispiel 1.</p>`,

  'curves.text': `
<h2>Unterteilung von Polygonen</h2>
<p><strong>Der Algorithmus von Chaikin</strong> (Abb. 7) ersetzt jede Kante durch die Punkte bei ¼ und
¾ ihrer Länge. Die Polygone konvergieren gegen den quadratischen B-Spline mit den ursprünglichen
Punkten als Kontrollpunkten; er berührt jede innere Kante in ihrem Mittelpunkt. Die Arbeit zählt
die Algorithmen von de Casteljau und de Boor zu den Unterteilungsalgorithmen dieser Art, die nicht
alle Eingabepunkte behalten (der von de Casteljau behält die beiden Endpunkte): Wiederholt
konvergieren sie gegen eine Bézier- bzw. B-Spline-Kurve. Ihre Regeln sind eigene, nicht Chaikins
Schnitte bei ¼ und ¾, außer für Grad 2: Die Mittelpunkte gleichabständiger Knoten in einen
quadratischen B-Spline einzufügen ist der Algorithmus von Chaikin.</p>
<p><strong>Das Vierpunktschema</strong> von Dyn, Levin und Gregory (Abb. 8) behält jeden Punkt und
fügt auf jeder Kante einen neuen ein:</p>
${display(`${sub('p', 'i + 1/2')}<mo>=</mo><mo>(</mo>${frac('<mn>1</mn>', '<mn>2</mn>')}<mo>+</mo><mi>w</mi><mo>)</mo><mo>(</mo>${sub('p', 'i')}<mo>+</mo>${sub('p', 'i + 1')}<mo>)</mo><mo>−</mo><mi>w</mi><mo>(</mo>${sub('p', 'i − 1')}<mo>+</mo>${sub('p', 'i + 2')}<mo>)</mo>`, '8')}
<p>Die Grenzkurve interpoliert die Daten. Abb. 8 der Arbeit verwendet w = 1/13 (im Feld neben dem
Regler exakt eintippen), und w = 1/16 reproduziert kubische Polynome; bei w = 0 ist die Grenzkurve das
Polygon selbst. Die Arbeit nennt die Grenzkurve C¹ für 0 &lt; w &lt; ⅛: Das ist die hinreichende
Bedingung, die Dyn, Levin und Gregory 1987 bewiesen haben, nicht die Stelle, an der Knicke entstehen.
Dyn, Gregory und Levin (1991) beweisen C¹ für 0 &lt; w &lt; (√5 − 1)/8 ≈ 0,155. Die scharfe Schranke
ist bekannt: Die Grenzkurve ist genau für 0 &lt; w &lt; w* C¹, und w* ≈ 0,19273 ist die reelle
Nullstelle von 32w³ + 4w − 1 = 0 (J. Hechler, B. Mößner und U. Reif, <em>C¹-continuity of the
generalized four-point scheme</em>, Linear Algebra Appl. 430, 2009, S. 3019–3029); dort erreicht der
gemeinsame Spektralradius des Schemas der dividierten Differenzen den Wert 1.</p>
<p><strong>Sehen, wie sich die Polygone strecken.</strong> Anzeige und Diagramm nennen den größten
Außenwinkel des verfeinerten Polygons, den größten Winkel zwischen einer Kante und der nächsten, nach
jedem Schritt bis ${TURNING_STEPS}, also über die gezeichneten hinaus. Wo er gegen 0 fällt, strecken sich die
Polygone; er zeigt, wie schnell, nicht ob die Grenzkurve C¹ ist. Auf diesem Polygon, geschlossen, ist er
nach ${TURNING_STEPS} Schritten für jedes w bis 0,17 kleiner als nach ${TURNING_FROM}, fällt dort aber nicht mehr gleichmäßig:
Bei w = 0,17 beträgt er nach ${TURNING_FROM - 2}, ${TURNING_FROM}, ${TURNING_STEPS - 2} und ${TURNING_STEPS} Schritten 1,15, 1,04, 1,19 und 1,00 rad. Ab w = 0,171
knickt das Polygon nach ${TURNING_STEPS} Schritten noch irgendwo um mehr als 1 rad ab: langsame Konvergenz oder
eine Spitze der Grenzkurve, wo ihre Ableitung verschwindet — auch eine C¹-Grenzkurve kann eine haben,
und die Winkel unterscheiden beides nicht. Jenseits von w* ≈ 0,193 (der Regler reicht bis 0,2) gibt es
keine C¹-Grenzkurve. Bei einem offenen
Polygon verwenden die Endkanten Geisterpunkte, extrapoliert aus den letzten vier Punkten, eine
Endregel von ruledlab (die Arbeit nennt keine); sie versagt zuerst: Dort fällt der Winkel nur bis
w = 0,126, während sich das geschlossene Polygon, das keine Enden hat, darüber hinaus noch streckt.</p>
<p class="rl-paper-data">Die Arbeit gibt für Abb. 7–8 kein Kontrollpolygon an; ruledlab verwendet acht
Punkte in einem offenen Zickzack (das Kontrollkästchen schließt ihn).</p>`,

  'strip.text': `
<h2>Variationelle Unterteilung eines Regelflächenstreifens (Beispiel 3)</h2>
<p>Die beiden Randkurven getrennt zu verfeinern übergeht die Fläche dazwischen. Das variationelle
Schema fügt zwischen je zwei Erzeugenden eine Erzeugende ${m(`${sub('A', 'i')}${sub('B', 'i')}`)} ein,
teilt alle Strecken in <em>n</em> Teile,</p>
${display(`${sub('z', 'i , k')}<mo>=</mo>${frac(row('n − k'), '<mi>n</mi>')}${sub('a', 'i')}<mo>+</mo>${frac('<mi>k</mi>', '<mi>n</mi>')}${sub('b', 'i')}`, '9')}
<p>und trianguliert den verfeinerten Streifen auf die beiden Arten von Abb. 9. In einem Knoten mit
sechs Nachbarn ist der <em>Umbrella-Vektor</em> (13) der Knoten abzüglich des Mittels seiner Nachbarn, eine
diskrete mittlere Krümmung; die neuen Endpunkte minimieren</p>
${display(`<mi>F</mi><mo>=</mo><munder><mo>∑</mo>${row('i , k')}</munder><mo>(</mo><msubsup><mi>U</mi>${row('i , k')}<mn>2</mn></msubsup><mo>+</mo><msubsup><mover><mi>U</mi><mo>~</mo></mover>${row('i , k')}<mn>2</mn></msubsup><mo>)</mo>`, '15')}
<p>eine quadratische Funktion, also ein lineares Gleichungssystem.</p>
<p class="rl-beyond"><strong>Was ruledlab ergänzt.</strong> Wörtlich gelesen, mit Umbrella-Vektoren nur
in den neuen Punkten, ist das Minimum genau die Mittelpunktsregel (wählen Sie „wörtlich“: Die Anzeige
gleicht der Mittelpunktsregel). Die <em>gekoppelte</em> Energie von ruledlab nimmt Umbrella-Vektoren in
jedem inneren Knoten, auch in den alten, sodass die neuen Erzeugenden gekoppelt sind und der Fläche
für jedes n von 5 bis 24 (der Regler reicht von 3 bis 24) enger folgen als die Mittelpunktsregel (für n = 3, 4
nicht). Die <em>gemittelte</em> Variante mittelt die Umbrella-Vektoren der beiden
Triangulierungen vor dem Quadrieren: Die Energie (15) enthält einen Verdrillungsterm aus den
gescherten Nachbarn der beiden Triangulierungen, den das Mitteln aufhebt. Auf dieser Fläche ist das
Vierpunktschema an der schlechtesten Erzeugenden am besten: Seine Randkurven sind quadratisch, was
w = 1/16 exakt reproduziert. Die Anzeige misst den Abstand der eingefügten Erzeugenden von der
exakten Fläche, für jedes Schema bei diesem n; die Aussagen darunter werden an diesen Zahlen geprüft.</p>
<p class="rl-paper-data">Daten aus der Arbeit: 12 Erzeugende der quartischen Fläche
(1 + vu², u²/2 + uv, u − v), n = 12; die Intervalle u ∈ [−1, 1] und v ∈ [−1, 1] (die Enden der
Erzeugenden) wählt ruledlab (die Arbeit nennt keines von beiden).</p>`,

  'congruence.text': `
<h2>Eine Geradenkongruenz verfeinern</h2>
<p>Eine <em>Geradenkongruenz</em> ist eine zweiparametrige Schar von Geraden, etwa die Lagen der
Achse eines Fräswerkzeugs über einer Fläche. Ihr diskretes Modell ist ein Gitter von Geraden
${m(sub('R', 'i , j'))}, jede gegeben durch ihre Punkte ${m(sub('p', 'i , j'))} und ${m(sub('q', 'i , j'))}
auf zwei Leitflächen ${m(sub('d', '1'))} und ${m(sub('d', '2'))} (Abb. 11). Die Kongruenz zu verfeinern
heißt, beide Punktgitter zu verfeinern.</p>
<p><strong>Butterfly-Schema (Abb. 12).</strong> Triangulieren Sie das Gitter durch die Diagonalen und
fügen Sie auf jeder Diagonale ein</p>
${display(`${sub('p̄', 'i , j')}<mo>=</mo>${frac('<mn>1</mn>', '<mn>2</mn>')}<mo>(</mo>${sub('p', 'i , j')}<mo>+</mo>${sub('p', 'i + 1 , j + 1')}<mo>)</mo><mo>+</mo><mn>2</mn><mi>w</mi><mo>(</mo>${sub('p', 'i + 1 , j')}<mo>+</mo>${sub('p', 'i , j + 1')}<mo>)</mo><mo>−</mo><mi>w</mi><mo>(</mo>${sub('p', 'i , j − 1')}<mo>+</mo>${sub('p', 'i − 1 , j')}<mo>+</mo>${sub('p', 'i + 1 , j + 2')}<mo>+</mo>${sub('p', 'i + 2 , j + 1')}<mo>)</mo>`, '16')}
<p>Die Arbeit fügt nur diese Geraden auf den Diagonalen ein (Abb. 13, „nur Diagonalen“) und nennt
keinen Wert des Spannungsparameters w; ruledlab verwendet w = 1/16, was kubische Polynome
reproduziert.</p>
<p><strong>Variationelle Unterteilung (Abschnitt 5.2, Abb. 15).</strong> Jede Zeile und Spalte von
Geraden ist eine Regelfläche: Das Streifenschema fügt die Geraden T und S auf den Kanten ein, und
jede Masche erhält die Gerade, deren Umbrella-Vektor (20) über ihre acht Nachbarn in jeder Schicht
verschwindet: deren Mittel. Wörtlich gelesen (Umbrella-Vektoren nur in den neuen Punkten) liefert das
Streifenschema die Mittelpunktsregel, das Schema der Arbeit („Arbeit“) ist also bilineare Mittelung
der vier Ecken.</p>
<p class="rl-beyond"><strong>Über die Arbeit hinaus.</strong> „Butterfly, alle Kanten“ wendet die
Schablone von (16) auch auf die beiden anderen Kantenrichtungen an, sodass ein Schritt das Gitter
verdoppelt. „Zweistufig“ bildet die Kantengeraden mit der gekoppelten Streifenenergie von ruledlab;
„gekoppelt“ lässt alle neuen Geraden gemeinsam in einem dünn besetzten System zur Ruhe kommen.
Die Anzeige misst das gezeigte Schema an der exakten Kongruenz und zum Vergleich die vier Schemata
des Menüs, die das ganze Gitter verfeinern, nach einem Schritt: Das Butterfly-Schema auf allen Kanten
ist bei diesen Beispielen am genauesten.</p>
<p class="rl-paper-data">Daten: Beispiel 5 stammt aus der Arbeit (d₁ = (u, v, ½ sin(2u + 1,5v)),
Richtungen (u, v, sin u + 1,3 cos v), 8 × 7 Geraden auf [−1,1; 1,1]², K = 6; wörtlich gelesen liefert das
Schema für jedes K dieselben Geraden, K wirkt sich also nicht auf das Ergebnis aus). Für die beiden Kongruenzen
aus Beispiel 4 gibt die Arbeit keine Formeln an; Kugel und hyperbolisches Paraboloid wählt ruledlab,
ebenso die Länge der Strecken (0,35 des Richtungsvektors).</p>`,

  'milling.text': `
<h2>Beispiel 6: eine glatte Bahn für ein Fräswerkzeug</h2>
<p>Einige Lagen eines Kugelfräsers sind entlang eines zu fräsenden Profils gegeben. Jede ist eine
Strecke von der Werkzeugspitze entlang der Werkzeugachse; die Lagen bilden also eine diskrete
Regelfläche, und deren Verfeinerung verfeinert die Bewegung. Nach einem Schritt (Abb. 16) folgt die
Bahn dem Profil schon enger; zwei und drei Schritte (Abb. 17, 18) lassen die Orientierung sich
glatt ändern. Die gestrichelte Kurve verbindet die Schwerpunkte des Werkzeugs; der durchscheinende
Schlauch ist die Hüllfläche der Kugel, deren untere Hälfte die gefräste Fläche ist. Das Werkzeug
selbst ist in einer Lage gezeichnet (Position verschieben oder abspielen).</p>
<p>Die Anzeige misst, was im CAM zählt: wie weit die gefräste Fläche das Sollprofil verfehlt (positiv
bleibt Material stehen, negativ wird zu viel abgetragen), die größte Änderung der
Werkzeugorientierung zwischen zwei Lagen und ihre zweite Differenz (wie gleichmäßig sich die
Orientierung dreht). Vergleichen Sie die Schemata an der Anzeige: Ab sieben Lagen lassen die
variationellen Schemata die kleinste Abweichung vom Profil (bei weniger kann das Vierpunktschema
näher liegen); die Mittelpunktsregel dreht das Werkzeug in den kleinsten Schritten (sie halbiert
jede Drehung), aber am wenigsten gleichmäßig, das gemittelte variationelle Schema am gleichmäßigsten. Das Diagramm zeigt die Abweichung
entlang der Bahn: je Lage, wie weit die Kugel vom Profil absteht; je Satz des G-Codes, wie weit die
lineare Interpolation der Steuerung von der Bahn abweicht (Spitze, und Achse mal Werkzeuglänge, in
mm bei 1 Einheit = 10 mm).</p>
<p>Die Schaltflächen exportieren die Bahn als JSON, CSV oder G-Code für die gewählte Maschine,
Steuerung (LinuxCNC, Heidenhain, Sinumerik) und Kinematik: Maschinenkoordinaten, von ruledlab
berechnet, oder die Werkzeugspitze (TCP), die die Steuerung umrechnet. Der Postprozessor fügt Lagen
ein, bis die Interpolation innerhalb von 0,01 mm bleibt, und das Programm beginnt und endet mit
sicheren Bewegungen entlang der Werkzeugachse (Handbuch, Teil „CAM“). Eigene Werkzeuglagen — eine CSV
mit Spitze x, y, z und Achse i, j, k je Zeile, JSON oder die hier exportierten Dateien — werden im
Datenbereich eingefügt oder hochgeladen („Werkzeuglagen“) und öffnen sich in dieser Szene.</p>
<p class="rl-paper-data">Die Arbeit gibt für Beispiel 6 keine Daten an; das Profil auf der
Werkstückfläche z = 0,3 sin x cos 0,7y, die sieben Lagen und das Werkzeug (Radius 0,25, Länge 1,5)
stammen von ruledlab.</p>`,

  'formula.text': `
<h2>Ihre eigene Regelfläche</h2>
<p>Tippen Sie die Leitkurve ${mr('a ( u )')} und die Richtung der Erzeugenden ${mr('e ( u )')} ein: Die
Fläche ist ${m(`${row('x ( u , v )')}<mo>=</mo>${row('a ( u ) + v e ( u )')}`)}. Formeln verwenden Zahlen
(mit Dezimalkomma oder -punkt: <code>0,5</code> oder <code>0.5</code>; in <code>atan2(y, x)</code> trennt das Komma
die Argumente), <code>u</code>, die Parameter <code>a</code>, <code>b</code>, <code>c</code>
(Regler), <code>pi</code>, <code>e</code>, die Operatoren <code>+ - * / ^</code> und die Funktionen
sin cos tan asin acos atan atan2 sinh cosh tanh exp ln log sqrt abs (log ist der natürliche
Logarithmus). Ein Fehler wird neben seinem Feld angezeigt, mit seiner Spalte.</p>
<p>Der Kern leitet die Formeln exakt ab (automatische Differentiation, ohne Schrittweite); die
<em>exakte</em> Kehllinie ${mr('s ( u )')}, der Drall und die Zentraltangente sind also so genau wie
bei den eingebauten Flächen, und jedes Werkzeug der Abschnitte 2–4 arbeitet auf Ihrer Fläche: das
Kehlpolygon, die Konvergenzordnungen, die Verbiegung, die Näherungsabwicklung und die Unterteilung.
Die Formeln sind Teil des Links: Teilen Sie ihn als Übungsaufgabe.</p>`,

  'focal.text': `
<h2>Brennflächen einer Geradenkongruenz</h2>
<p class="rl-beyond"><strong>Über die Arbeit hinaus.</strong> Die Arbeit verfeinert Kongruenzen
(Abschnitt 5), berechnet aber nicht ihre Geometrie. Längs einer Geraden ${mr('p + t e')} der
Kongruenz ${mr('p ( u , v ) + t e ( u , v )')}, mit ${m('<mi>e</mi>')} der Länge 1, sind die
<em>Brennpunkte</em> die Punkte, in denen die Gerade ihre unendlich benachbarten Geraden in den beiden
Torsalrichtungen (unten) schneidet: die Nullstellen von</p>
${display(`<mo>det</mo><mo>(</mo>${sub('p', 'u')}<mo>+</mo><mi>t</mi>${sub('e', 'u')}<mo>,</mo>${sub('p', 'v')}<mo>+</mo><mi>t</mi>${sub('e', 'v')}<mo>,</mo><mi>e</mi><mo>)</mo><mo>=</mo><mn>0</mn>`, 'F1')}
<p>Zwei reelle Nullstellen machen die Gerade <em>hyperbolisch</em> (durchgezogen), keine
<em>elliptisch</em> (gestrichelt), eine doppelte <em>parabolisch</em>. (Nachbargeraden in jeder
anderen Richtung schneiden die Gerade nicht: Sie kommen ihr in ihren <em>Zentralpunkten</em> am
nächsten, die zwischen den beiden Grenzpunkten liegen.) Bewegt sich die Gerade,
überstreichen ihre Brennpunkte die beiden <em>Brennflächen</em> (schattiert, wo reell). Längs einer
<em>Torsalrichtung</em> ${mr('( du : dv )')} bilden die Geraden einen abwickelbaren Streifen durch
einen Brennpunkt,</p>
${display(`<mo>det</mo><mo>(</mo>${sub('p', 'u')}<mi>du</mi><mo>+</mo>${sub('p', 'v')}<mi>dv</mi><mo>,</mo><mi>e</mi><mo>,</mo>${sub('e', 'u')}<mi>du</mi><mo>+</mo>${sub('e', 'v')}<mi>dv</mi><mo>)</mo><mo>=</mo><mn>0</mn>`, 'F2')}
<p>(Striche auf der Leitfläche ${m(sub('d', '1'))}). Die <em>Normalität</em> ist |cos| des Winkels
der beiden Brennebenen: 0 für die Normalen einer Fläche, deren Brennpunkte die
Hauptkrümmungsmittelpunkte sind — probieren Sie das Ellipsoid. Ein Feld von Werkzeugachsen beim
5-Achs-Fräsen ist eine Kongruenz: Wo eine Brennfläche dem Werkstück nahe kommt, schneiden sich
benachbarte Achsen dort (beinahe); wo ihre Geraden elliptisch werden, haben sie keine reellen
Brennpunkte, und benachbarte Achsen laufen windschief aneinander vorbei.</p>
<p>ruledlab berechnet all das allein aus den Geraden: aus ihren Plücker-Koordinaten, über das Gitter
differenziert (zentral im Inneren, über drei Geraden am Rand). Das Ergebnis hängt nicht davon ab,
wo die Punkte p und q auf ihren Geraden liegen, bewegt sich exakt mit Bewegungen mit und
konvergiert von zweiter Ordnung, auch am Rand (Handbuch, „Focal geometry and linear complexes“). Die Anzeige passt
außerdem den <em>linearen Komplex</em>
${m(`<mi>c</mi><mo>·</mo><mi>m</mi><mo>+</mo><mover><mi>c</mi><mo>‾</mo></mover><mo>·</mo><mi>d</mi><mo>=</mo><mn>0</mn>`)}
an, der die Geraden am besten enthält: die Treffgeraden zweier windschiefer Geraden liegen in
zweien (eine lineare Kongruenz).</p>
<p class="rl-paper-data">Daten: die Kongruenz von Beispiel 5 stammt aus der Arbeit; die beiden
Kongruenzen von Beispiel 4 (die Arbeit nennt für sie keine Daten), das Ellipsoid (Halbachsen 1,6;
1,2; 0,8), die zwei windschiefen Geraden und die elliptische Kongruenz wählt ruledlab.</p>`,

  'formulaCongruence.text': `
<h2>Ihre eigene Geradenkongruenz</h2>
<p>Tippen Sie einen Punkt ${mr('p ( u , v )')} der Leitfläche ${m(sub('d', '1'))} und die Richtung
${mr('e ( u , v )')} der Geraden ein: Die Kongruenz enthält die Geraden ${mr('p ( u , v ) + t e ( u , v )')}.
Das Gitter der Geraden (Zeilen entlang u, Spalten entlang v) wird mit den Schemata aus Abschnitt 5
verfeinert. Die Vorlagen enthalten die Normalen eines Ellipsoids (eine Normalenkongruenz) und die
Geraden, die zwei windschiefe Geraden treffen.</p>`,

  'lines.text': `
<h2>Die Geraden verfeinern, nicht ihre Endpunkte</h2>
<p>Jedes Schema aus Abschnitt 4 arbeitet mit zwei gewählten Punkten je Erzeugende. Verschieben Sie
diese Punkte entlang ihrer Erzeugenden (Regler): Die Geraden ändern sich nicht, aber die vom
Vierpunktschema auf den Endpunkten verfeinerte Fläche (gestrichelt) schon: Sie hängt von einer Wahl
ab, die nicht zur Geometrie gehört.</p>
<p class="rl-beyond"><strong>Über die Arbeit hinaus.</strong> ruledlab kann auch die Geraden selbst
verfeinern. Eine orientierte Gerade mit Richtung e durch p ist der duale Einheitsvektor
${mr('e + ε ( p × e )')}. Die Vierpunktregel (8) wird auf diese Vektoren angewandt und jedes Ergebnis auf
die duale Einheitskugel zurückgeführt: eine neue Gerade. Die verfeinerten Geraden hängen dann nur von
den gegebenen Geraden ab, und die Konstruktion ist mit Bewegungen vertauschbar; sie ist wie das
Endpunktschema von vierter Ordnung. Die Anzeige zeigt, wie weit sich die neuen Erzeugenden jedes
Schemas durch das Verschieben gedreht haben.</p>`,

  'large.text': `
<h2>Große Modelle</h2>
<p>Eine Wendelfläche mit bis zu 10 000 Erzeugenden, verfeinert durch bis zu sieben Schritte des
Vierpunktschemas: bis zu 1 280 000 Erzeugende (die Grenze der Bibliothek liegt bei 4 194 304 je
Fläche; darüber wird mit einer klaren Meldung abgelehnt). Kleine Aufgaben werden sofort berechnet;
alles Größere läuft in einem Web Worker mit einer eigenen Kopie des WebAssembly-Moduls, sodass die
Seite weiter zeichnet und antwortet, während sich der Fortschrittsbalken füllt (Abbrechen beendet
es). Über ${grouped(DRAW_LIMIT)} Erzeugenden zeichnet die Ansicht jede k-te Erzeugende, eine Detailstufe, und sagt
das unter der Anzeige.</p>`,

  'data.text': `
<h2>Ihre eigenen Erzeugenden</h2>
<p>Ihre Erzeugenden oder Ihr Raster von Geraden kommen aus dem Datenbereich der Seite, aus „Als Daten
bearbeiten“ in einer als Formeln eingegebenen Szene oder aus einem Notebook (NumPy-Arrays, gesendet mit
<code>View.from_segments</code> oder <code>View.from_grid</code>). Im Datenbereich fügen Sie eine
CSV-Datei mit sechs Zahlen je Zeile ein oder laden sie hoch (a.x a.y a.z b.x b.y b.z; eine Kopfzeile
ist erlaubt), oder JSON: <code>[[ax, ay, az, bx, by, bz], …]</code>, oder
<code>{"rows": r, "cols": c, "segments": […]}</code> für eine Kongruenz. Eine fehlerhafte Datei wird mit
Zeile und Spalte des Fehlers abgelehnt, und die bisher gezeigten Daten bleiben. Eine Regelfläche wird
mit ihrem Kehlpolygon und den gemeinsamen Loten gezeigt, ein Raster von Geraden mit seiner Leitfläche
(und seinen Brennflächen, wenn Sie sie wählen); die Export-Schaltflächen speichern sie wieder oder
ihre Invarianten. Auf der Seite stehen kleine Importe (bis ${MAX_LINK_RULINGS} Erzeugende) im Link,
größere im Sitzungsspeicher dieses Browser-Tabs.</p>`,
};
