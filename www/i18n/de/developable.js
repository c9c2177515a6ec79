// Deutsche Texte der Szene „Papiermodelle“: abwickelbare Streifen und ihre Schnittmuster
// (Abschnitt 3, über das Paper hinaus).
// Keys: developable.*

export default {
  'developable.title': 'Papiermodelle: abwickelbare Streifen',
  'developable.param.kind': 'Streifen',
  'developable.kind.tangent': 'Tangentenfläche einer Schraublinie',
  'developable.kind.cone': 'Kegel über einer Schraublinie',
  'developable.kind.cylinder': 'Zylinder über einer Schraublinie',
  'developable.kind.rectifying': 'rektifizierende Torse einer Schraublinie',
  'developable.kind.hyperboloid': 'Hyperboloid (nicht abwickelbar)',
  'developable.param.turns': 'Windungen der Schraublinie',
  'developable.param.width': 'Breite des Streifens',
  'developable.param.repair': 'Nachbarn in einer Ebene halten',
  'developable.legend.pattern': 'Schnittmuster',
  'developable.legend.overlap': 'Flächen, die sich in der Ebene überlappen',
  'developable.readout.delta': 'größtes |δ| eines Paares',
  'developable.readout.isometry': 'größte relative Längenänderung, Muster gegen Streifen',
  'developable.readout.pieces': 'auszuschneidende Teile',
  'developable.readout.turns': 'Windungen der Schraublinie',
  'developable.readout.gap': 'größte Lücke h eines Paares',
  'developable.readout.climb': 'die Lücken aufsummiert (der Anstieg)',
  'developable.describe':
    'Der Streifen „{kind}“ mit {n} Erzeugenden, je zwei benachbarte in einer Ebene, neben seinem exakten Schnittmuster (auszuschneidende Teile: {pieces}).',
  'developable.describeApproximate':
    'Der Streifen „{kind}“ mit {n} Erzeugenden neben der näherungsweisen Abwicklung aus Abschnitt 3, die bei jedem Paar von Erzeugenden eine Lücke lässt; auszuschneidende Teile: {pieces}.',
  'developable.download.svg': 'Schnittmuster (SVG, 1:1 in mm)',
  'developable.download.dxf': 'Schnittmuster (DXF R12, für Laserschneider)',
  'developable.download.a4': 'Schnittmuster auf A4-Seiten (ZIP mit SVGs, mit Passermarken)',
  'developable.download.letter': 'Schnittmuster auf Letter-Seiten (ZIP mit SVGs, mit Passermarken)',
  'developable.from': 'der Streifen „{kind}“',
  'developable.text': `
<p>Eine Regelfläche ist <em>abwickelbar</em> (eine Torse), wenn sie sich ohne Dehnen in die Ebene
legen lässt: ein gebogenes, nicht zerknittertes Blatt Papier. Diskret liegen je zwei benachbarte
Erzeugende in einer Ebene (ihr Verteilungsparameter δ ist 0); jede Fläche zwischen ihnen ist ein
ebenes Viereck, und der Streifen lässt sich Fläche für Fläche in die Ebene abwickeln, jede Länge und
jeder Winkel bleibt erhalten.</p>
<p>Die Streifen hier entstehen so aus einer Schraublinie: ihre <em>Tangentenfläche</em> (die
Erzeugenden längs der Kanten des Polygons), ein <em>Kegel</em> und ein <em>Zylinder</em> über ihr
und ihre <em>rektifizierende Torse</em>, auf der die Schraublinie eine Geodätische ist und sich auf
eine Gerade abwickelt. Ziehen Sie an einer Erzeugenden: Der Streifen folgt, und der Kern dreht ihre
Nachbarn, bis wieder jedes Paar in einer Ebene liegt. Ist <em>Nachbarn in einer Ebene halten</em>
aus, bleibt der Streifen, wie Sie ihn ziehen: Machen Sie ihn von Hand abwickelbar, indem Sie ein
Ende einer Erzeugenden auf die nächste Erzeugende einrasten lassen (zwei Geraden, die sich
schneiden, liegen in einer Ebene).</p>
<p>Das Schnittmuster steht neben dem Streifen. Wo es sich selbst überlappt (eine Tangentenfläche
über mehr als eine Windung ihrer abgewickelten Kante), wird es in Teile zerlegt, die das nicht tun,
und längs einer Erzeugenden geklebt. Laden Sie es als SVG im Maßstab 1:1 in Millimetern, mit einem
Prüfquadrat von 100 mm, auf A4- oder Letter-Seiten mit Passermarken verteilt, oder als DXF für
einen Laserschneider, und bauen Sie das Modell.</p>
<p>Das <em>Hyperboloid</em> ist nicht abwickelbar: Seine benachbarten Erzeugenden sind windschief.
Abschnitt 3 wickelt es näherungsweise ab, über sein konoidales Modell; das Muster behält die Länge
jeder Erzeugenden, verliert aber den Abstand h benachbarter Erzeugender. Ein Papiermodell davon
schließt sich nicht: Die Lücken summieren sich längs des Streifens.</p>`,
};
