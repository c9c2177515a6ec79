// Deutsche Texte zu den Abbildungen und Beispielen der Arbeit: das Menü, die Bildunterschriften
// (übersetzt zitiert), was ruledlab jeweils zeigt und wo es über die Arbeit hinausgeht.
// Keys: paper.*

export default {
  'paper.none': '— keine —',
  'paper.heading': 'Aus der Arbeit: {figure}',
  'paper.changed': 'Sie haben die Einstellungen der Abbildung geändert.',
  'paper.back': 'Zurück zu {figure}',
  'paper.beyondTitle': 'Über die Arbeit hinaus.',
  'paper.data.paper': 'Daten: aus der Arbeit.',
  'paper.data.partly': 'Daten: teils aus der Arbeit (siehe oben).',
  'paper.data.none': 'Daten: Die Arbeit gibt keine an; Wahl von ruledlab (siehe oben).',
  'paper.fig1': 'Abb. 1: Bezeichnungen',
  'paper.fig2': 'Abb. 2: Kehllinie und gemeinsame Normalen (gemeinsame Lote)',
  'paper.fig3': 'Abb. 3: diskrete Zentralkurve (Kehllinie)',
  'paper.fig4': 'Abb. 4: konoidales Modell',
  'paper.fig5': 'Abb. 5: Schraubregelfläche, Bildunterschrift trifft nicht zu',
  'paper.fig5-orthogonal': 'Abb. 5: Schraubregelfläche, Bildunterschrift trifft zu',
  'paper.fig6': 'Abb. 6: Näherungsabwicklung',
  'paper.fig7': 'Abb. 7: Algorithmus von Chaikin',
  'paper.fig8': 'Abb. 8: Vierpunktschema, w = 1/13',
  'paper.fig9': 'Abb. 9: Bezeichnungen am Streifen',
  'paper.fig10': 'Abb. 10: verfeinerter Streifen der Quartik',
  'paper.fig11': 'Abb. 11: Kongruenz zwischen zwei Leitflächen',
  'paper.fig12': 'Abb. 12: Butterfly-Schema',
  'paper.fig13': 'Abb. 13 links: Kugel',
  'paper.fig13-right': 'Abb. 13 rechts: hyperbolisches Paraboloid',
  'paper.fig14': 'Abb. 14: Bezeichnungen an der Kongruenz',
  'paper.fig15': 'Abb. 15: Beispiel 5 verfeinert',
  'paper.fig16': 'Abb. 16: Werkzeugbahn, erster Schritt',
  'paper.fig17': 'Abb. 17: Werkzeugbahn, zweiter Schritt',
  'paper.fig18': 'Abb. 18: Werkzeugbahn, dritter Schritt',
  'paper.ex1': 'Beispiel 1: Hyperboloid',
  'paper.ex2': 'Beispiel 2: Verbiegen zum Konoid',
  'paper.ex3': 'Beispiel 3: Streifen der Quartik',
  'paper.ex4': 'Beispiel 4: Butterfly auf Kongruenzen',
  'paper.ex5': 'Beispiel 5: variationelle Kongruenz',
  'paper.ex6': 'Beispiel 6: Fräsen',
  'paper.fig1.caption': '„Diskretes Regelflächenmodell: Bezeichnungen.“ (übersetzt)',
  'paper.fig1.note':
    'Drei aufeinanderfolgende Erzeugende R_{i−1}, R_i, R_{i+1} mit den gemeinsamen Loten N_{i,i+1}, den Fußpunkten f_{i,i+1}, f_{i+1,i}, dem Winkel φ_{i,i+1} und dem vorzeichenbehafteten Abstand h_{i,i+1} (sein Betrag ist der Abstand der beiden Erzeugenden, sein Vorzeichen der Windungssinn (Schraubsinn) des Paares). Die Arbeit gibt keine Daten an; ruledlab verwendet drei Erzeugende des Hyperboloids aus Beispiel 1 (Abstand und Lage sind Schieberegler).',
  'paper.fig2.caption':
    '„Diskretes Modell einer Regelfläche mit Kehllinie und der Folge der gemeinsamen Normalen der Erzeugenden.“ (übersetzt)',
  'paper.fig2.note':
    'Das Hyperboloid x² + y²/4 − z²/9 = 1 aus Beispiel 1 (aus der Arbeit) mit den gemeinsamen Loten und dem Kehlpolygon m_i aus Satz 2. Die Zahl der Erzeugenden (36) und die Länge der Strecken wählt ruledlab: Die Arbeit nennt beides nicht.',
  'paper.fig3.caption': '„Diskretes Modell einer Regelfläche mit diskreter Zentralkurve.“ (übersetzt)',
  'paper.fig3.note':
    'Das Polygon, das Beispiel 1 beschreibt: die Mittelpunkte (f_{i,i+1} + f_{i+1,i})/2 der gemeinsamen Lote, auf dem Hyperboloid der Arbeit mit 36 Erzeugenden (Zahl von ruledlab).',
  'paper.fig3.beyond':
    'Das ist nicht das Kehlpolygon m_i aus Satz 2, das der Text als diskrete Kehllinie verwendet: Es nähert die Kehllinie zwischen zwei Erzeugenden, bei u + H/2, ebenfalls mit zweiter Ordnung. Schalten Sie das Kehlpolygon dazu, um beide zu sehen; die Anzeige misst jedes.',
  'paper.fig4.caption':
    '„Diskretes Regelflächenmodell (links) und dazu isometrisches konoidales Modell (rechts).“ (übersetzt)',
  'paper.fig4.note':
    'Die Gelenkkette ganz in ihr konoidales Modell gedreht (t = 1), die Fläche selbst blass dahinter, in einer Ansicht statt nebeneinander (die Anordnung in drei Feldern ist Abb. 6). Die Arbeit gibt keine Daten an; ruledlab verwendet 24 Erzeugende der Quartik aus Beispiel 3.',
  'paper.fig5.caption':
    '„Links: Schraubregelfläche. Rechts: isometrische konoidale Fläche. In diesem Fall ist das Ergebnis eine Schraubfläche, deren Erzeugende die Achse senkrecht schneiden.“ (übersetzt)',
  'paper.fig5.note':
    'Eine Schraubregelfläche, in ihr konoidales Modell verbogen. Die Arbeit gibt keine Daten an; ruledlab verwendet Radius 1, Schraubparameter 0,4 (Höhe je Radiant: z = 0,4 u, also Ganghöhe 2π · 0,4 ≈ 2,51) und Erzeugende unter 45°.',
  'paper.fig5-orthogonal.note':
    'Dieselbe Schraublinie mit Erzeugenden normal zur Kehlschraublinie (tan β = −r/p), der Fall, in dem die Bildunterschrift zutrifft: Die Anzeige ρ strebt gegen 0, die konoidalen Erzeugenden treffen im Grenzwert die Achse. Die Arbeit gibt keine Daten an; die Fläche wählt ruledlab.',
  'paper.fig5.beyond':
    'Die Bildunterschrift trifft nur zu, wenn die Erzeugenden die Kehllinie rechtwinklig kreuzen (e·ṡ = 0); das sagt die Arbeit nicht. Im Allgemeinen berühren die konoidalen Erzeugenden einen Zylinder um die Achse mit Radius ρ = (e·ṡ)/|e′|, für diese Flächen r + p tan β: 1,4 unter 45°, 0 im rechten Winkel. Die Anzeige misst ρ, die Aussagen darunter werden geprüft.',
  'paper.fig6.caption':
    '„Näherungsabwicklung einer windschiefen Regelfläche auf Grund der diskreten Darstellung: links das diskrete Modell einer windschiefen Regelfläche, in der Mitte das isometrische konoidale diskrete Modell, rechts die Projektion der diskreten konoidalen Fläche normal zu ihren Erzeugenden.“ (übersetzt)',
  'paper.fig6.note':
    'Die drei Felder von Abb. 6: ein Streifen des Hyperboloids aus Beispiel 1, sein konoidales Modell und die Abwicklung, in der das Bild des Kehlpolygons dem von den abgewickelten Erzeugenden eingehüllten Polygon (gestrichelt) eingeschrieben ist; die Anzeige nennt die Höhe des konoidalen Modells, das Maß der Nichtabwickelbarkeit. Die Arbeit gibt keine Daten an; den Streifen (24 Erzeugende, u von 0 bis 2,4) wählt ruledlab.',
  'paper.fig7.caption': '„Algorithmus von Chaikin.“ (übersetzt)',
  'paper.fig7.note':
    'Vier Schritte des Algorithmus von Chaikin, jede Stufe gezeichnet. Die Arbeit gibt kein Kontrollpolygon an; ruledlab verwendet acht Punkte in einem offenen Zickzack.',
  'paper.fig8.caption': '„Interpolierende Unterteilung nach Dyn, Levin und Gregory (w = 1/13).“ (übersetzt)',
  'paper.fig8.note':
    'Vier Schritte von (8) mit dem w = 1/13 der Arbeit, exakt (tippen Sie einen Bruch in das Feld neben dem Schieberegler). Die Arbeit gibt kein Kontrollpolygon an; ruledlab verwendet acht Punkte in einem offenen Zickzack.',
  'paper.fig9.caption':
    '„Grundlegende Bezeichnungen für einen unterteilten Regelflächenstreifen, die beiden verschiedenen Triangulierungen.“ (übersetzt)',
  'paper.fig9.note':
    'Die Bezeichnungen a_i, b_i, A_i, B_i, z_{i,k}, Z_{i,k} am Streifen der Quartik aus Beispiel 3 mit der ersten Triangulierung (11); die zweite (12) im Menü (ruledlab zeichnet je eine). n = 6 statt der 12 aus Beispiel 3, damit man die Dreiecke lesen kann.',
  'paper.fig10.caption':
    '„12 Erzeugende einer quartischen Regelfläche R, 11 Geraden eingefügt; hellgraue Kugeln um A_i, dunkelgraue Kugeln um B_i.“ (übersetzt)',
  'paper.fig10.note':
    'Beispiel 3 mit den Daten der Arbeit: 12 Erzeugende von (1 + vu², u²/2 + uv, u − v), n = 12, ein Schritt der Energie (15) wörtlich gelesen; Kugeln um A_i (hell) und B_i (dunkel). Die Intervalle u ∈ [−1, 1] und v ∈ [−1, 1] (die Enden der Erzeugenden) wählt ruledlab: Die Arbeit nennt keines von beiden.',
  'paper.strip.beyond':
    'Wörtlich gelesen setzt (15) Umbrella-Vektoren nur in die neuen Punkte, und das Minimum ist genau die Mittelpunktsregel (unter der Anzeige geprüft). Die gekoppelte und die gemittelte Energie von ruledlab setzen sie in jeden Knoten; die Anzeige vergleicht jedes Schema bei diesem n: Gekoppelt schlägt die Mittelpunktsregel für jedes n von 5 bis 24 (nicht für n = 3, 4), und das Vierpunktschema ist auf dieser Fläche exakt.',
  'paper.fig11.caption': '„Durch zwei Leitflächen bestimmte Geradenkongruenz.“ (übersetzt)',
  'paper.fig11.note':
    'Die Geraden aus Beispiel 5 zwischen den Leitflächen d₁ und d₂, beide schattiert. Die Abbildung der Arbeit ist eine Skizze; ruledlab nimmt für d₂ die Punkte p + 0,35 d (die Arbeit nennt keine Länge der Strecken).',
  'paper.fig12.caption': '„Das Butterfly-Schema.“ (übersetzt)',
  'paper.fig12.note':
    'Die Schablone von (16) ist neben der Ansicht mit allen Gewichten gezeichnet; die Ansicht zeigt die Geraden, die sie auf den Diagonalen des Gitters aus Beispiel 5 einfügt (ein Schritt, wie in der Arbeit). Den Spannungsparameter w = 1/16 wählt ruledlab (er reproduziert kubische Polynome): Die Arbeit nennt keinen Wert.',
  'paper.fig13.caption':
    '„Links: Teil einer Kugel mit Geraden der Kongruenz (schwarz, dünn) und eingefügten Geraden (schwarz, dick). Rechts: Teil eines hyperbolischen Paraboloids, Geraden der Kongruenz (schwarz, dünn), eingefügte Geraden (schwarz, dick).“ (übersetzt)',
  'paper.fig13.note':
    'Abb. 13 links: Geraden nur auf den Diagonalen eingefügt, wie in der Arbeit, mit w = 1/16 in (16) (Wahl von ruledlab: Die Arbeit nennt keinen Wert). Für Beispiel 4 gibt die Arbeit keine Formeln an; die Kugel von ruledlab trägt die Richtungen Normale + 0,3 (sin 2v, cos 3u, uv), eine verallgemeinerte Offsetfläche, keine Normalenkongruenz. Eingefügte Geraden sind farbig statt dick schwarz gezeichnet. Die Anzeige misst diese Diagonalgeraden; die Zeilen „zum Vergleich“ gehören zu anderen Schemata (die Butterfly-Zeile fügt auf allen Kanten ein).',
  'paper.fig13-right.note':
    'Abb. 13 rechts: Geraden nur auf den Diagonalen eingefügt, mit w = 1/16 in (16) (Wahl von ruledlab: Die Arbeit nennt keinen Wert). Für Beispiel 4 gibt die Arbeit keine Formeln an; das hyperbolische Paraboloid z = xy von ruledlab trägt die Richtungen (−v, −u, 1) + 0,3 (cos 2v, sin u, 0). Die Anzeige misst diese Diagonalgeraden; die Zeilen „zum Vergleich“ gehören zu anderen Schemata (die Butterfly-Zeile fügt auf allen Kanten ein).',
  'paper.fig14.caption':
    '„Punktschema auf der Leitfläche d₁ (links), Teil der Kongruenz mit einigen Bezeichnungen (rechts).“ (übersetzt)',
  'paper.fig14.note':
    'Die Bezeichnungen aus Abschnitt 5.2 an einer Masche von Beispiel 5: die gegebenen Geraden R_{i,j} mit ihren Punkten p auf d₁ und q auf d₂, die Kantengeraden T_{i,j} (Punkte r, r′) und S_{i,j} (s, s′) und die Maschengerade R̄_{i,j} (Punkte P, Q). T läuft über jede Zeile, 1 ≤ j ≤ N₂ (das N₂ − 1 des Texts ließe die letzte aus).',
  'paper.fig15.caption':
    '„Diskrete Geradenkongruenz (links), eingefügte Geraden (schwarz, dick) (rechts).“ (übersetzt)',
  'paper.fig15.note':
    'Beispiel 5 mit den Daten der Arbeit: d₁ = (u, v, ½ sin(2u + 1,5v)), Richtungen (u, v, sin u + 1,3 cos v), 8 × 7 Geraden auf [−1,1; 1,1]², K = 6, einmal verfeinert mit dem wörtlich gelesenen variationellen Schema der Arbeit: Kantengeraden nach der Mittelpunktsregel, jede Maschengerade das Mittel ihrer acht Nachbarn. So gelesen wirkt sich K nicht auf das Ergebnis aus: Jedes K liefert dieselben Geraden.',
  'paper.congruence.beyond':
    'Wörtlich gelesen liefern die Energien (15) und (21) bloße Mittelwerte; ruledlab bietet außerdem „zweistufig“ (seine gekoppelte Streifenenergie auf den Kanten), „gekoppelt“ (alle neuen Geraden in einem dünn besetzten System) und das Butterfly-Schema auf allen Kanten. Die Anzeige misst das gezeigte Schema und zum Vergleich alle vier nach einem Schritt; auf jeder eingebauten Kongruenz ist das Butterfly-Schema auf allen Kanten am genauesten (unter der Anzeige geprüft).',
  'paper.fig16.caption': '„Erster Schritt der Verfeinerung.“ (übersetzt)',
  'paper.fig16.note':
    'Beispiel 6 nach einem Schritt: gegebene Werkzeugachsen dunkel, eingefügte hell, das Werkzeug als Zylinder mit Kugelende, die Schwerpunktkurve gestrichelt, die überstrichene Kugel über dem Werkstück. Die Arbeit gibt keine Daten an; Profil, sieben Lagen und Werkzeug (Radius 0,25, Länge 1,5) stammen von ruledlab.',
  'paper.fig17.caption': '„Zweiter Schritt der Verfeinerung.“ (übersetzt)',
  'paper.fig17.note': 'Beispiel 6 nach zwei Schritten (Daten von ruledlab, wie in Abb. 16).',
  'paper.fig18.caption': '„Dritter Schritt der Verfeinerung.“ (übersetzt)',
  'paper.fig18.note': 'Beispiel 6 nach drei Schritten (Daten von ruledlab, wie in Abb. 16).',
  'paper.milling.beyond':
    'Die Arbeit verfeinert die Bahn „wie in Abschnitt 4 beschrieben“; wörtlich gelesen ist diese Energie die Mittelpunktsregel („linear“ im Menü). ruledlab verwendet stattdessen seine gekoppelte Energie; die Anzeige nennt die Abweichung jedes Schemas vom Profil, und die Aussagen darunter sagen, wo die variationellen Schemata am nächsten kommen.',
  'paper.ex1.caption':
    'Beispiel 1: eine diskretisierte Regelschar des Hyperboloids x² + y²/4 − z²/9 = 1 mit seiner Kehllinie.',
  'paper.ex1.note':
    'Beide diskreten Kehlpolygone, m_i aus Satz 2 und die Lotmittelpunkte, die der Text von Beispiel 1 beschreibt, gegen die exakte Kehllinie; die Anzeige misst jedes. Das Hyperboloid stammt aus der Arbeit, die 36 Erzeugenden von ruledlab.',
  'paper.ex2.caption': 'Beispiel 2: Jede Regelfläche lässt sich isometrisch auf eine konoidale Regelfläche abbilden.',
  'paper.ex2.note':
    'Die Gelenkkette der Quartik aus Beispiel 3 auf halbem Weg (t = 0,5) zwischen der Fläche und ihrem konoidalen Modell; verschieben Sie t oder spielen Sie es ab. Die Anzeige der Kantenlängen zeigt, dass die Verbiegung bis auf Rundung isometrisch ist. Die Arbeit gibt keine Daten an.',
  'paper.ex3.caption':
    'Beispiel 3: N = 12 Erzeugende der quartischen Regelfläche (1 + vu², u²/2 + uv, u − v), n = 12, ein Schritt der variationellen Unterteilung.',
  'paper.ex3.note':
    'Beispiel 3 mit den Daten der Arbeit, der ersten Triangulierung und der exakten Fläche blass dahinter; die Anzeige misst den Abstand der eingefügten Erzeugenden von der Fläche für jedes Schema. Die Intervalle u ∈ [−1, 1] und v ∈ [−1, 1] (die Enden der Erzeugenden) wählt ruledlab: Die Arbeit nennt keines von beiden.',
  'paper.ex4.caption':
    'Beispiel 4: das Butterfly-Schema auf Kongruenzen mit zwei verschiedenen Leitflächen d₁; d₂, eine verallgemeinerte Offsetfläche, ist in der Arbeit nicht gezeichnet.',
  'paper.ex4.note':
    'Die Kugel aus Abb. 13 mit Geraden nur auf den Diagonalen (w = 1/16, Wahl von ruledlab: Die Arbeit nennt keinen Wert), dazu d₂ schattiert (das die Arbeit nicht zeichnet). Für Beispiel 4 gibt die Arbeit keine Formeln an; die Kongruenz wählt ruledlab. Die Anzeige misst die gezeigten Diagonalgeraden; die Zeilen „zum Vergleich“ gehören zu anderen Schemata (die Butterfly-Zeile fügt auf allen Kanten ein).',
  'paper.ex5.caption':
    'Beispiel 5: d₁ = (u, v, ½ sin(2u + 1,5v)), Geraden parallel zu (u, v, sin u + 1,3 cos v), 8 × 7 Werte auf [−1,1; 1,1]², K = 6.',
  'paper.ex5.note':
    'Beispiel 5 mit den Daten der Arbeit, einmal mit dem wörtlich gelesenen Schema der Arbeit verfeinert, mit beiden Leitflächen (d₂ = p + 0,35 d: Die Arbeit nennt keine Länge der Strecken). Wörtlich gelesen wirkt sich K = 6 nicht auf das Ergebnis aus: Jedes K liefert dieselben Geraden (ebenso beim gekoppelten Schema von ruledlab; nur „zweistufig“ hängt von K ab).',
  'paper.ex6.caption':
    'Beispiel 6: einige Lagen eines Fräswerkzeugs entlang eines Profils, durch die variationelle Unterteilung aus Abschnitt 4 zu einer glatten Bahn verfeinert.',
  'paper.ex6.note':
    'Zwei Schritte, das Werkzeug weiter entlang der Bahn. Die Arbeit gibt keine Daten an; Profil, Lagen und Werkzeug stammen von ruledlab.',
};
