// The built-in exercises: a set along the paper, in English and German, each tested to be
// solvable (its solution state passes the check) and not solved at its start
// (tests/node/task.test.mjs). Their data (a start edit, a solution edit) are the page's own, made
// once from the scenes' input and written here; their mathematics is the paper's (Sections 2–5)
// and the core's.
import { readTask } from './format.js';
import { congruenceFields, surfaceFields } from '../catalogue.js';

/** Only the fields `keys` of `fields` (a solution sets what the exercise lets change). */
const pick = (/** @type {Record<string, unknown>} */ fields, /** @type {string[]} */ keys) =>
  Object.fromEntries(keys.map((k) => [k, fields[k]]));

/** Edits made once from the scenes' own input (a ruling of the cone lifted, a tool pose lifted, …). */
const TORSAL_SOLUTION =
  'rulings.AAAAAAAA8D8AAAAAAAAAwAAAAAAAAAjAAAAAAAAA8D8AAAAAAAAAQAAAAAAAAAhAzDt_Zp6g9j8AAAAAAACwvAAAAAAAAAjAAAAAAAAAoDzMO39mnqAGQAAAAAAAAAhAAAAAAAAA8D__________PwAAAAAAAAjAyzt_Zp6g5r_MO39mnqD2PwAAAAAAAAAAAAAAAAAAoDzMO39mnqAGQAAAAAAAAAjAzDt_Zp6g9r8AAAAAAACwPAAAAAAAAAhA________778BAAAAAAAAQAAAAAAAAAjAAQAAAAAA8L__________vwAAAAAAAAhAzTt_Zp6g9r8AAAAAAADAPAAAAAAAAAjAAAAAAAAAsLzNO39mnqAGwAAAAAAAAAhAAQAAAAAA8L_-________vwAAAAAAAAjA_v______7z8BAAAAAAAAwAAAAAAAAAhAAAAAAAAAuLzMO39mnqAGwAAAAAAAAAjAzDt_Zp6g9j8AAAAAAADIvAAAAAAAAAhA';
const CONE_START =
  'rulings.zczMzMzM7D-amZmZmZnJvzMzMzMzM_M_MzMzMzMzB0CamZmZmZnJv5qZmZmZmQFACbBiQEiO7D8Q4lrwiZ_EvzMzMzMzM_M_DQiUYGzVBkCIznp3EQuhP5qZmZmZmQFAzA3-TR3V6z-7rg6jL6y_vzMzMzMzM_M_shT99Ku_BUDo-WmLuH3QP5qZmZmZmQFA5WWfwFyo6j_qqQLFC9i2vzMzMzMzM_M_1xjvIIv8A0AhAXxY7rvdP5qZmZmZmQFAng9qdoAT6T9g_z52zDGuvzMzMzMzM_M_bBefsUCdAUA8YKhTU63kP5qZmZmZmQFAq_VeRvsl5z_s9NFi1nShvzMzMzMzM_M_AOEc0_Fx_T8mRPGaL3TpP5qZmZmZmQFAjzrmF6Ly5D9gvZnBjtaPvzMzMzMzM_M_rq-yR-bX9j9Altmd4gPtP5qZmZmZmQFAjClJ7vOO4j8gVHNPyodwvzMzMzMzM_M_R_m2lbdZ7z8OmEaEojnvP5qZmZmZmQFA_R0P7UcS4D8AAPY17BvKvjMzMzMzM_M_7LNajq9t4D8Qrx3W2P_vP5qZmZmZmQFAUATgsNIp2z_A1IH-xYFtvzMzMzMzM_M_EM8AKoHXpz8E9Qhc9U7vP5qZmZmZmQFAnyIUilRe1j8AcINIVRiOvzMzMzMzM_M_RDCHwwTK2b-ArTMBuC3tP83MzMzMzARApDUPCuzw0T_EOeZJ2NKgvzMzMzMzM_M_FF_S4Tst6r9Wqknk7rDpP5qZmZmZmQFAzuaujbEZzD88XjkLjWOtvzMzMzMzM_M_5dK81brs8r-qfMobq_rkP5qZmZmZmQFAkvXloDmwxT-6zGXBul62vzMzMzMzM_M_0YdTx9S797_pTOfd53HeP5qZmZmZmQFA6FSA0xLkwD-qVrdiTiW_vzMzMzMzM_M_UsBf4fFU-78B_uxrCkjRP5qZmZmZmQFAgOqKcjTIuz8IJZz541fEvzMzMzMzM_M_EOgLVeyU_b9Qh1yZoMKnP5qZmZmZmQFAQPKHVzubuT_bFvEvelDJvzMzMzMzM_M_KAUtv8ll_r8hiaYf3eLHv5qZmZmZmQFAxBZ7EntWuz_dxwGx2kvOvzMzMzMzM_M_dtcR2ZG__b-WVwUTkOPav5qZmZmZmQFAygYB54R0wD_EA_yLrYzRvzMzMzMzM_M_6Dq_Upyo-79MC_SjCKbkv5qZmZmZmQFAaPwwLTwOxT9ej4uQCMXTvzMzMzMzM_M_skIb3lI1-L8YrqKxGU_rv5qZmZmZmQFASKQC9XJLyz-yg2h5TrnVvzMzMzMzM_M_ygQ-yGmH87-KxRy29ZXwv5qZmZmZmQFA8PIsgpt30T-fQVFoaFbXvzMzMzMzM_M_Lid5eS2Z679t4nmcnAHzv5qZmZmZmQFAAq5M03PX1T9tIm0Gk4zYvzMzMzMzM_M_7uszDEnz3L-js6OJ3NL0v5qZmZmZmQFAuPOHVYea2j80gBx_-E_ZvzMzMzMzM_M_gGwStP80eL9MwKq-9Pf1v5qZmZmZmQFA';
const DEVELOPABLE_SOLUTION =
  'rulings.AAAAAAAA8D-amZmZmZkBwGdmZmZmZgrAAAAAAAAA8D8zMzMzMzPjv8zMzMzMzOy_AAAAAAAA8D-amZmZmZkBwGdmZmZmZgrAV5MZtHOe8D-whXSpVAPLP8zMzMzMzOy_AAAAAAAA8D-amZmZmZkBwGdmZmZmZgrA8AA_hWdq7T9Q7X6Pqq3vP8zMzMzMzOy_AAAAAAAA8D-amZmZmZkBwGdmZmZmZgrArhiAEXgd5T_e8zE28OP5P8zMzMzMzOy_';
const MILLING_START =
  'poses.uA9c_utesL9NF1zj5purv-BBcOA4j3K_Y0LTWNZ8vL-QjhlOcEHRP9LE2JeuWfc_3fssFErS7T8rJLqSlJLpP_JfhzVgDcw_ju2L-ZpD8j_cBBkY5bbzPyImGKEhPfo_zttNRXXE_j91nR0aO__1P6B_272DeMY_-ALJ7cfnA0AP1hiPu_n7P1nPP66KOPg_H75ZA3BgB0B68Qsrz6P3P4u0Hv4nRNY_cy-9epnzDEBz_SthY6L2Pw2gva2ty_o_817TDop5D0B4wlKHP-jwP7elsBiQZsK_9r7X-A0xEkA4sVnynZLkP_s26eZWk_I_ILBxILa_E0Ba5caWqwjRP7pHCJnTitG_MKgr9azAFEDYOQR-aui6vxa0DJK3hPI_V88zShq8F0DQIh8pgpvjv0pd8F3uL7S_hz1hlpHUF0BCqPVD0S_svx_B04xGWfY_';
const LINES_SOLUTION =
  'rulings.AAAAAAAA8D9i4iIB8onMv2LiIgHyicy_AAAAAAAA8D_Hy1h0QhvuP8XLWHRCG-4_bUx-5sST8j_6IG3mpUDMP3KkFG2kHdW_Nriq-sse3z9kHV5ANj7uP37LzmRAH-U_IhnN8fCG7D9r_d6Hrw7uPzjZgDaWhMy_DpK3shAKxr_8UOewTDzwP9hQ92Qx_uo_bHrv6akl4L8rHP9vRxfsPyypVZy4t-c_QNREibav9L_n1FI0i-bOP2jE6vezEfw_liKHMoTW67-PX3wrknfvP0ZSCklHWtY_Cq4PmTat8b90W1oFJUHlv1_WiHiSGwBAh3kCzpWM8r-Ny0yL0NC1vwilQGieCO0_f9V8K8Zb5r8NQw9UXOPnv779H6dDafs_xiU-bbnL3L_HYU4Ie6HtvwbzBOnF4vg_nryR30UpyD-7CgKR4ATxvwMR5bV_qwFA55NnXC1b1L8CrJhlaKn1v5nXwLvcIvI_ZLBWrhhe9T9wcZUw_43Xvy9eRQMLeAhAafTfw4WS6z_SoE4gxcbjv-ishhz8YABAX3yk8AMk8j9_QHX7Nk3UP7hVswXIKwhA';
/** The eight tangents of a helix (the Klein scene's), the end b of R_5 lifted by 0.3 along z; and as they were. */
const COMPLEX_START =
  'rulings.AAAAAAAA8D-amZmZmZm5P7gehetRuJ4_AAAAAAAA8D8zMzMzMzPzPwrXo3A9Ctc__r1x8CZz4T9GqeC-hgPrP6yy9ahkJ9M_QqBc7Swk1L8KsaN19Xr4P-WbcH0OI-Q_b1H52Bp71L8TDqz_UXzuP7aJmRmiMeI_vNTIUmlH9r9coT7BI6fmP0VMj0L-wOw_B6WqrSw47r9GmeKRmgDWPxY6uN6Rz-o_v2EhbP6-9r8KmaE-grbkv1L-1gN3r_I_2xPspUxx678eX4AEc8Tgvzt169HAtvE_yuqn9vhW2L9noglGoT34v4JWZuZu_vY_LOgRFOwAwL_AxAUL5ujvv2vNerS4BfY_toYQNApR7j-8mLkkCt_zv7894coZDQBApB2m1Bp05j9REysrAAbnv5slCpewVPo_4hXjHaz8-D9gqEXsvzmhv-IGhatenP8_AAAAAAAA8D-ImZmZmZm5P8t9mXmoo_4_AQAAAAAA8D8yMzMzMzPzP4kvCker9QFA';
const COMPLEX_SOLUTION =
  'rulings.AAAAAAAA8D-amZmZmZm5P7gehetRuJ4_AAAAAAAA8D8zMzMzMzPzPwrXo3A9Ctc__r1x8CZz4T9GqeC-hgPrP6yy9ahkJ9M_QqBc7Swk1L8KsaN19Xr4P-WbcH0OI-Q_b1H52Bp71L8TDqz_UXzuP7aJmRmiMeI_vNTIUmlH9r9coT7BI6fmP0VMj0L-wOw_B6WqrSw47r9GmeKRmgDWPxY6uN6Rz-o_v2EhbP6-9r8KmaE-grbkv1L-1gN3r_I_2xPspUxx678eX4AEc8Tgvzt169HAtvE_yuqn9vhW2L9noglGoT34v4JWZuZu_vY_LOgRFOwAwL_AxAUL5ujvv2vNerS4BfY_toYQNApR7j-8mLkkCt_zv7Ku9chmTfs_pB2m1Bp05j9REysrAAbnv5slCpewVPo_4hXjHaz8-D9gqEXsvzmhv-IGhatenP8_AAAAAAAA8D-ImZmZmZm5P8t9mXmoo_4_AQAAAAAA8D8yMzMzMzPzP4kvCker9QFA';

const RAW = [
  {
    id: 'striction-accuracy',
    title: { en: 'How many rulings for {tol}?', de: 'Wie viele Erzeugende für {tol}?' },
    prompt: {
      en: 'The striction polygon m_i converges to the exact striction curve with order 2 (Proposition 2): doubling the number of rulings N divides its error by about 4. Starting from N = {n}, choose N so that the polygon is within {tol} of the exact curve at every interior ruling of the quartic surface (m_i exists only there). The readout shows the error and the measured order.',
      de: 'Das Kehlpolygon m_i konvergiert mit der Ordnung 2 gegen die exakte Kehllinie (Satz 2): Eine Verdopplung der Zahl N der Erzeugenden teilt seinen Fehler etwa durch 4. Wählen Sie, ausgehend von N = {n}, N so, dass das Polygon an jeder inneren Erzeugenden der quartischen Fläche (nur dort gibt es m_i) höchstens {tol} von der exakten Kehllinie entfernt ist. Die Messwerte zeigen den Fehler und die gemessene Ordnung.',
    },
    scene: 'striction',
    // every student her own start and tolerance (task/draw.js); the check is the core's at her N
    draw: { n: { from: 8, to: 16 }, tol: { list: [2e-3, 1e-3, 5e-4] } },
    params: { surface: 'quartic', n: { drawn: 'n' }, exact: true, normals: false },
    change: ['n'],
    goal: [{ value: 'readout.midpointError', below: { drawn: 'tol' } }],
    hints: [
      {
        en: 'Read the error at N = {n} in the readout, and divide it by {tol}: that is the factor by which it has to shrink.',
        de: 'Lesen Sie den Fehler bei N = {n} in den Messwerten ab und teilen Sie ihn durch {tol}: So viel kleiner muss er werden.',
      },
      {
        en: 'With order 2 the error falls like 1/N² (strictly, like the square of the spacing, 1/(N − 1)²): N − 1 must grow by about the square root of that factor. From N = 12, for 10⁻³: the error 0.017 must shrink 17-fold, so N − 1 grows by √17 ≈ 4.1, from 11 to about 46.',
        de: 'Bei Ordnung 2 fällt der Fehler wie 1/N² (genau: wie das Quadrat der Schrittweite, 1/(N − 1)²): N − 1 muss etwa um die Wurzel dieses Faktors wachsen. Von N = 12 aus, für 10⁻³: Der Fehler 0,017 muss auf ein Siebzehntel schrumpfen, also wächst N − 1 um √17 ≈ 4,1, von 11 auf etwa 46.',
      },
    ],
    // (within every tolerance drawn: about 2·10⁻⁴ at N = 100)
    solution: { params: { n: 100 } },
  },
  {
    id: 'torsal-pair',
    title: { en: 'Make a pair of rulings torsal', de: 'Ein torsales Paar von Erzeugenden' },
    prompt: {
      en: 'Two consecutive rulings are a torsal pair when they meet: their distance h and the distribution parameter δ = h/φ are then 0. Drag an end of one ruling until it meets its neighbour: the smallest |δ| of a pair below 0.01.',
      de: 'Zwei aufeinanderfolgende Erzeugende bilden ein torsales Paar, wenn sie sich schneiden: Ihr Abstand h und der Drall δ = h/φ sind dann 0. Ziehen Sie ein Ende einer Erzeugenden, bis sie ihre Nachbarin schneidet: das kleinste |δ| eines Paares unter 0,01.',
    },
    scene: 'striction',
    params: { surface: 'hyperboloid', n: 8, normals: true },
    change: ['handles'],
    goal: [{ value: 'striction.minAbsDelta', below: 0.01 }],
    hints: [
      {
        en: 'Two lines meet when a point of one lies on the other: move an end of a ruling onto the line of its neighbour.',
        de: 'Zwei Geraden schneiden sich, wenn ein Punkt der einen auf der anderen liegt: Bringen Sie ein Ende einer Erzeugenden auf die Gerade ihrer Nachbarin.',
      },
      {
        en: 'Drag the end near the neighbouring ruling: it snaps onto that line exactly (◆ “on ruling …” beside it), and δ of the pair, shown beside the end, becomes 0. Snapping is on unless the ◈ button in the ✎ bar (or S) turned it off.',
        de: 'Ziehen Sie das Ende nahe an die benachbarte Erzeugende: Es rastet genau auf dieser Geraden ein (◆ „auf der Erzeugenden …“ daneben), und δ des Paares, neben dem Ende angezeigt, wird 0. Das Einrasten ist an, solange die Schaltfläche ◈ in der ✎-Leiste (oder S) es nicht ausgeschaltet hat.',
      },
    ],
    solution: { input: TORSAL_SOLUTION },
  },
  {
    id: 'minding-delta',
    title: { en: 'What bending keeps', de: 'Was das Verbiegen erhält' },
    prompt: {
      en: 'The readout shows δ of the middle pair of rulings of this surface. Bent to its conoidal model (t = 1), what will δ of that pair be? Type your prediction.',
      de: 'Die Messwerte zeigen δ des mittleren Paares von Erzeugenden dieser Fläche. Welchen Wert hat δ dieses Paares, wenn die Fläche zu ihrem konoidalen Modell verbogen ist (t = 1)? Geben Sie Ihre Vorhersage ein.',
    },
    scene: 'isometry',
    // the hyperboloid of Example 1: δ of the middle pair is far from 0 (the quartic's middle pair
    // straddles its torsal ruling u = 0, where δ ≤ 0 vanishes, and shows only discretisation error)
    params: { surface: 'hyperboloid', layout: 'bend', n: 24, t: 0 },
    change: [],
    answers: [{ id: 'delta', kind: 'number', label: { en: 'δ after bending', de: 'δ nach dem Verbiegen' } }],
    goal: [{ answer: 'delta', near: { value: 'isometry.deltaBentMiddle' }, within: 2e-4 }],
    hints: [
      {
        en: 'A discrete Minding isometry (Section 3) moves each pair of consecutive rulings, with its common perpendicular, as one rigid body; the bodies turn about the rulings as hinges. What does it keep of the pair?',
        de: 'Eine diskrete Minding-Isometrie (Abschnitt 3) bewegt jedes Paar aufeinanderfolgender Erzeugender samt gemeinsamem Lot als starren Körper; die Körper drehen sich um die Erzeugenden als Gelenke. Was bleibt von dem Paar erhalten?',
      },
      {
        en: 'It keeps the angle φ and the signed distance h of consecutive rulings, so δ = h/φ stays what it is.',
        de: 'Sie erhält den Winkel φ und den vorzeichenbehafteten Abstand h aufeinanderfolgender Erzeugender, also bleibt δ = h/φ, wie es ist.',
      },
    ],
    solution: { answers: { delta: -1.7110714 } },
  },
  {
    id: 'developable-cone',
    title: { en: 'Make the cone developable again', de: 'Den Kegel wieder abwickelbar machen' },
    prompt: {
      en: 'A cone is developable: all its rulings pass through one point, every δ is 0 and its conoidal model is flat. One ruling has been moved away. Move it back so that the surface is developable again: its conoidal model less than 0.005 high.',
      de: 'Ein Kegel ist abwickelbar: Alle seine Erzeugenden gehen durch einen Punkt, jedes δ ist 0 und sein konoidales Modell ist flach. Eine Erzeugende wurde verschoben. Bewegen Sie sie zurück, so dass die Fläche wieder abwickelbar ist: ihr konoidales Modell weniger als 0,005 hoch.',
    },
    scene: 'isometry',
    params: { surface: 'cone', layout: 'bend', n: 24, t: 0 },
    input: CONE_START,
    change: ['handles'],
    goal: [{ value: 'isometry.readout.nonDevelopability', below: 0.005 }],
    hints: [
      {
        en: 'The rulings of a cone meet in its vertex: find the one that misses it.',
        de: 'Die Erzeugenden eines Kegels treffen sich in seiner Spitze: Finden Sie diejenige, die sie verfehlt.',
      },
      {
        en: 'Ruling 10 was lifted by 0.4 at its end b: move that end straight down. Press ✎ and choose ↕ (along z), then drag the end — hold it a moment first to move it finely, and watch the height beside it; with a mouse, Alt while dragging does the same. Or tap the end and type its z under the view.',
        de: 'Erzeugende 10 wurde an ihrem Ende b um 0,4 angehoben: Bewegen Sie dieses Ende senkrecht nach unten. Tippen Sie auf ✎ und wählen Sie ↕ (längs z), dann ziehen Sie das Ende – erst einen Moment halten, um es fein zu bewegen, und die Höhe daneben beobachten; mit der Maus tut Alt beim Ziehen dasselbe. Oder tippen Sie das Ende an und geben Sie sein z unter der Ansicht ein.',
      },
    ],
    solution: {},
  },
  {
    id: 'one-piece',
    title: { en: 'A paper model in one piece', de: 'Ein Papiermodell aus einem Stück' },
    prompt: {
      en: 'The tangent surface of a helix is developable: its flat pattern keeps every length. Over one and a half turns the pattern overlaps itself and must be cut into pieces. Choose the turns of the helix so that the pattern is one piece, with at least one full turn.',
      de: 'Die Tangentenfläche einer Schraublinie ist abwickelbar: Ihr Schnittmuster erhält jede Länge. Über anderthalb Windungen überlappt sich das Muster und muss in Teile zerlegt werden. Wählen Sie die Windungen der Schraublinie so, dass das Muster aus einem Stück besteht, mit mindestens einer vollen Windung.',
    },
    scene: 'developable',
    params: { kind: 'tangent', n: 60, turns: 1.5, width: 1.2 },
    change: ['turns'],
    goal: [
      { value: 'developable.readout.pieces', below: 1.5 },
      { value: 'developable.readout.turns', above: 0.99 },
    ],
    hints: [
      {
        en: 'The edge of regression unrolls onto a circle: per turn of the helix it turns through 2π/√(1 + 0.4²) ≈ 5.83 rad, a little less than a full turn.',
        de: 'Die Gratlinie wickelt sich auf einen Kreis ab: Je Windung der Schraublinie dreht sie sich um 2π/√(1 + 0,4²) ≈ 5,83 rad, etwas weniger als eine volle Umdrehung.',
      },
    ],
    solution: { params: { turns: 1 } },
  },
  {
    id: 'make-developable',
    title: { en: 'Make this strip developable', de: 'Diesen Streifen abwickelbar machen' },
    prompt: {
      en: 'These four rulings of a hyperboloid are not a developable strip: no two neighbours lie in one plane, so its flat pattern can only be approximate. Drag the ends of the rulings until every two neighbouring rulings lie in one plane — the largest |δ| of a pair 0 — and the pattern beside it is exact.',
      de: 'Diese vier Erzeugenden eines Hyperboloids sind kein abwickelbarer Streifen: Keine zwei Nachbarn liegen in einer Ebene, daher kann sein Schnittmuster nur näherungsweise sein. Ziehen Sie die Enden der Erzeugenden, bis je zwei benachbarte Erzeugende in einer Ebene liegen – das größte |δ| eines Paares 0 – und das Muster daneben exakt ist.',
    },
    scene: 'developable',
    params: { kind: 'hyperboloid', n: 4, turns: 0.25, width: 0.8, repair: false },
    change: ['handles'],
    goal: [{ value: 'developable.readout.delta', below: 1e-9 }],
    hints: [
      {
        en: 'Two lines lie in one plane when they meet (or are parallel). Rulings that all pass through one point make a cone, and a cone is developable.',
        de: 'Zwei Geraden liegen in einer Ebene, wenn sie sich schneiden (oder parallel sind). Erzeugende, die alle durch einen Punkt gehen, bilden einen Kegel, und ein Kegel ist abwickelbar.',
      },
      {
        en: 'Press ✎ and drag end a of ruling 1 onto end a of ruling 0: it snaps onto that point (◆ on ruling 0, end a), and the pair meets exactly. Do the same with end a of rulings 2 and 3.',
        de: 'Tippen Sie auf ✎ und ziehen Sie Ende a der Erzeugenden 1 auf Ende a der Erzeugenden 0: Es rastet auf diesem Punkt ein (◆ auf Erzeugende 0, Ende a), und das Paar schneidet sich exakt. Ebenso mit Ende a der Erzeugenden 2 und 3.',
      },
    ],
    solution: { input: DEVELOPABLE_SOLUTION },
  },
  {
    id: 'chaikin-count',
    title: { en: 'Count Chaikin’s points', de: 'Chaikins Punkte zählen' },
    prompt: {
      en: 'Chaikin’s corner cutting replaces each edge of an open polygon by two points, at ¼ and ¾ of it. Starting from these 8 control points, how many points does the polygon have after {steps} steps?',
      de: 'Chaikins Eckenabschneiden ersetzt jede Kante eines offenen Polygons durch zwei Punkte bei ¼ und ¾ ihrer Länge. Wie viele Punkte hat das Polygon nach {steps} Schritten, ausgehend von diesen 8 Kontrollpunkten?',
    },
    scene: 'curves',
    // every student her own number of steps; the count the check compares with is the core's
    draw: { steps: { from: 2, to: 4 } },
    params: { scheme: 'chaikin', steps: { drawn: 'steps' }, closed: false, levels: true },
    change: [],
    hide: ['curves.readout.points'],
    answers: [
      { id: 'count', kind: 'number', label: { en: 'points after {steps} steps', de: 'Punkte nach {steps} Schritten' } },
    ],
    // (a count: 49.6 is not one)
    goal: [{ answer: 'count', near: { value: 'curves.readout.points' }, within: 0.001 }],
    hints: [
      { en: 'An open polygon of n points has n − 1 edges.', de: 'Ein offenes Polygon mit n Punkten hat n − 1 Kanten.' },
      { en: 'After one step: 2 · (8 − 1) = 14 points.', de: 'Nach einem Schritt: 2 · (8 − 1) = 14 Punkte.' },
    ],
    solution: { answers: { count: { value: 'curves.readout.points' } } },
  },
  {
    id: 'coupled-strip',
    title: { en: 'When coupling pays', de: 'Wann sich die Kopplung lohnt' },
    prompt: {
      en: 'ruledlab’s coupled energy (beyond the paper: read literally, (13)–(15) give the midpoint rule) inserts rulings into Example 3’s quartic surface. For large n, the number of parts of each segment, it comes closer to the exact surface than the midpoint rule — but not for every n. What is the smallest n for which the coupled scheme’s inserted rulings are closer to the surface than the midpoint rule’s?',
      de: 'ruledlabs gekoppelte Energie (über die Arbeit hinaus: wörtlich gelesen ergeben (13)–(15) die Mittelpunktsregel) fügt Erzeugende in die quartische Fläche aus Beispiel 3 ein. Für großes n, die Zahl der Teile jeder Strecke, kommt sie der exakten Fläche näher als die Mittelpunktsregel – aber nicht für jedes n. Für welches kleinste n liegen die vom gekoppelten Schema eingefügten Erzeugenden näher an der Fläche als die der Mittelpunktsregel?',
    },
    scene: 'strip',
    params: { scheme: 'coupled', n: 3, exact: true },
    change: ['n'],
    hide: ['claims', 'text'],
    answers: [{ id: 'n', kind: 'number', label: { en: 'the smallest n', de: 'das kleinste n' } }],
    // (tests/node/task.test.mjs computes the scene at n = 4 and 5: 5 is the core's answer)
    goal: [{ answer: 'n', near: 5, within: 0.5 }],
    hints: [
      {
        en: 'The readout lists every scheme’s distance from the quartic at this n.',
        de: 'Die Messwerte nennen bei diesem n den Abstand jedes Schemas von der quartischen Fläche.',
      },
      { en: 'Try n = 3, 4, 5, … in turn.', de: 'Versuchen Sie n = 3, 4, 5, … der Reihe nach.' },
    ],
    solution: { params: { n: 5 }, answers: { n: 5 } },
  },
  {
    id: 'congruence-scheme',
    title: { en: 'A close scheme in one step', de: 'Ein genaues Schema in einem Schritt' },
    prompt: {
      en: 'Refine the congruence of Example 5 once. Choose a scheme whose inserted lines make an angle of less than 10⁻³ rad with the exact congruence’s lines.',
      de: 'Verfeinern Sie die Kongruenz aus Beispiel 5 einmal. Wählen Sie ein Schema, dessen eingefügte Geraden mit den Geraden der exakten Kongruenz einen Winkel unter 10⁻³ rad einschließen.',
    },
    scene: 'congruence',
    params: { congruence: 'example5', scheme: 'paper', steps: 1 },
    change: ['scheme'],
    hide: [
      'congruence.readout.compare.paper',
      'congruence.readout.compare.two-stage',
      'congruence.readout.compare.coupled',
      'congruence.readout.compare.butterfly',
      'claims',
      'text',
    ],
    goal: [{ value: 'congruence.readout.angle', below: 1e-3 }],
    hints: [
      {
        en: 'The variational schemes minimise an energy of the new lines; the butterfly scheme (16) averages the neighbouring lines’ points on the two director surfaces with fixed weights.',
        de: 'Die variationellen Schemata minimieren eine Energie der neuen Geraden; das Butterfly-Schema (16) mittelt die Punkte der Nachbargeraden auf den beiden Leitflächen mit festen Gewichten.',
      },
      {
        en: 'Try each scheme and watch the angle in the readout.',
        de: 'Probieren Sie jedes Schema und beobachten Sie den Winkel in den Messwerten.',
      },
      {
        en: 'Both butterfly variants pass, on purpose: on Example 5 the largest angle is that of the lines (16) inserts on the diagonals, which the two share; the variational schemes miss by about 5·10⁻³ rad or more.',
        de: 'Beide Varianten des Butterfly-Schemas bestehen, mit Absicht: Auf Beispiel 5 ist der größte Winkel der der Geraden, die (16) auf den Diagonalen einfügt, und die haben beide gemeinsam; die variationellen Schemata verfehlen um etwa 5·10⁻³ rad oder mehr.',
      },
    ],
    // either butterfly variant (all edges, or the diagonals only) is a solution
    solution: { params: { scheme: 'butterfly' } },
  },
  {
    id: 'tool-back',
    title: { en: 'Put the tool back on the part', de: 'Das Werkzeug zurück auf das Werkstück' },
    prompt: {
      en: 'One tool pose has been lifted off the part: the machined surface misses the target profile by far. Move it back so that the refined tool path misses the profile by less than 0.02.',
      de: 'Eine Werkzeuglage wurde vom Werkstück abgehoben: Die gefräste Fläche verfehlt das Sollprofil weit. Bewegen Sie sie zurück, so dass die verfeinerte Werkzeugbahn das Sollprofil um weniger als 0,02 verfehlt.',
    },
    scene: 'milling',
    params: { poses: 7, steps: 1, scheme: 'variational', tool: true, envelope: true, part: true },
    input: MILLING_START,
    change: ['handles'],
    goal: [{ value: 'milling.readout.deviation', below: 0.02 }],
    hints: [
      {
        en: 'The target profile is drawn wide and light: the tool’s ball should roll along it.',
        de: 'Das Sollprofil ist breit und hell gezeichnet: Die Kugel des Werkzeugs soll darauf abrollen.',
      },
      {
        en: 'Pose 3 was lifted by 0.3: move its tip straight down — the tool comes with it. Press ✎ and choose ↕ (along z), then drag the tip (hold it a moment first to move it finely, and watch the deviation beside it); with a mouse, Alt while dragging does the same. Or tap the tip and type its z under the view.',
        de: 'Werkzeuglage 3 wurde um 0,3 angehoben: Bewegen Sie ihre Spitze senkrecht nach unten – das Werkzeug kommt mit. Tippen Sie auf ✎ und wählen Sie ↕ (längs z), dann ziehen Sie die Spitze (erst einen Moment halten, um sie fein zu bewegen, und die Abweichung daneben beobachten); mit der Maus tut Alt beim Ziehen dasselbe. Oder tippen Sie die Spitze an und geben Sie ihr z unter der Ansicht ein.',
      },
    ],
    solution: {},
  },
  {
    id: 'hypar-striction',
    title: {
      en: 'The striction curve of the hyperbolic paraboloid',
      de: 'Die Kehllinie des hyperbolischen Paraboloids',
    },
    prompt: {
      en: 'The hyperbolic paraboloid z = xy is the ruled surface a(u) + v·e(u) with a(u) = (u, 0, 0) and e(u) = (0, 1, u). Compute its striction curve s(u) and type it.',
      de: 'Das hyperbolische Paraboloid z = xy ist die Regelfläche a(u) + v·e(u) mit a(u) = (u, 0, 0) und e(u) = (0, 1, u). Berechnen Sie seine Kehllinie s(u) und geben Sie sie ein.',
    },
    scene: 'formula',
    params: { preset: 'hyperbolic-paraboloid', tool: 'striction', exact: false },
    change: [],
    hide: ['exact'],
    answers: [{ id: 's', kind: 'curve', label: { en: 's(u)', de: 's(u)' } }],
    goal: [{ answer: 's', matches: 'striction', within: 1e-6 }],
    hints: [
      {
        en: 'The striction point of the ruling at u is a(u) − (a′·ê′)/(ê′·ê′) · ê(u), with ê = e/|e| the unit direction.',
        de: 'Der Kehlpunkt der Erzeugenden bei u ist a(u) − (a′·ê′)/(ê′·ê′) · ê(u), mit der Einheitsrichtung ê = e/|e|.',
      },
      {
        en: 'Here a′ = (1, 0, 0), and ê′ has no x-component.',
        de: 'Hier ist a′ = (1, 0, 0), und ê′ hat keine x-Komponente.',
      },
    ],
    solution: { answers: { s: ['u', '0', '0'] } },
  },
  {
    id: 'hyperboloid-striction',
    title: { en: 'The striction curve of the hyperboloid', de: 'Die Kehllinie des Hyperboloids' },
    prompt: {
      en: 'The hyperboloid of Example 1 is a(u) + v·e(u) with a(u) = (cos u, 2 sin u, 0) and e(u) = (−sin u, 2 cos u, 3). Compute its striction curve s(u) and type it (you may write a, b, c for 1, 2, 3).',
      de: 'Das Hyperboloid aus Beispiel 1 ist a(u) + v·e(u) mit a(u) = (cos u, 2 sin u, 0) und e(u) = (−sin u, 2 cos u, 3). Berechnen Sie seine Kehllinie s(u) und geben Sie sie ein (für 1, 2, 3 dürfen Sie a, b, c schreiben).',
    },
    scene: 'formula',
    params: { preset: 'hyperboloid', tool: 'striction', exact: false },
    change: [],
    hide: ['exact'],
    answers: [{ id: 's', kind: 'curve', label: { en: 's(u)', de: 's(u)' } }],
    goal: [{ answer: 's', matches: 'striction', within: 1e-6 }],
    hints: [
      {
        en: 'For any direction e(u), the striction point is a + λ e with λ = −((a′·e′)(e·e) − (a′·e)(e·e′)) / ((e′·e′)(e·e) − (e·e′)²).',
        de: 'Für jede Richtung e(u) ist der Kehlpunkt a + λ e mit λ = −((a′·e′)(e·e) − (a′·e)(e·e′)) / ((e′·e′)(e·e) − (e·e′)²).',
      },
      {
        en: 'Here a′·e′ = e·e′ = −3 sin u cos u, a′·e = 1 + 3 cos²u, e·e = 10 + 3 cos²u and e′·e′ = 1 + 3 sin²u.',
        de: 'Hier ist a′·e′ = e·e′ = −3 sin u cos u, a′·e = 1 + 3 cos²u, e·e = 10 + 3 cos²u und e′·e′ = 1 + 3 sin²u.',
      },
      {
        en: 'It comes to λ = 27 sin u cos u / (13 + 27 sin²u).',
        de: 'Es ergibt sich λ = 27 sin u cos u / (13 + 27 sin²u).',
      },
    ],
    solution: {
      answers: {
        s: [
          'cos(u) - sin(u)*27*sin(u)*cos(u)/(13+27*sin(u)^2)',
          '2*sin(u) + 2*cos(u)*27*sin(u)*cos(u)/(13+27*sin(u)^2)',
          '3*27*sin(u)*cos(u)/(13+27*sin(u)^2)',
        ],
      },
    },
  },
  {
    id: 'hypar-distribution',
    title: {
      en: 'The distribution parameter of the hyperbolic paraboloid',
      de: 'Der Drall des hyperbolischen Paraboloids',
    },
    prompt: {
      en: 'For the hyperbolic paraboloid z = {k}·xy, the ruled surface a(u) + v·e(u) with a(u) = (u, 0, 0), e(u) = (0, 1, {k}·u), compute the distribution parameter δ(u) and type it (you may write a for {k}).',
      de: 'Berechnen Sie für das hyperbolische Paraboloid z = {k}·xy, die Regelfläche a(u) + v·e(u) mit a(u) = (u, 0, 0), e(u) = (0, 1, {k}·u), den Drall δ(u) und geben Sie ihn ein (für {k} dürfen Sie a schreiben).',
    },
    scene: 'formula',
    // every student her own factor k (the formula field ez is a·u, a the drawn k): the exact δ(u)
    // the check compares with is the core's for it
    draw: { k: { list: [-3, -2, 2, 3] } },
    params: { preset: 'hyperbolic-paraboloid', tool: 'striction', ez: 'a*u', a: { drawn: 'k' } },
    change: [],
    hide: ['readout.meanDelta'],
    answers: [{ id: 'delta', kind: 'function', label: { en: 'δ(u)', de: 'δ(u)' } }],
    goal: [{ answer: 'delta', matches: 'distribution', within: 1e-6 }],
    hints: [
      {
        en: 'For any direction e(u): δ = det(a′, e, e′) · (e·e) / |e × e′|².',
        de: 'Für jede Richtung e(u) gilt δ = det(a′, e, e′) · (e·e) / |e × e′|².',
      },
      {
        en: 'Here det(a′, e, e′) = {k} and e × e′ = ({k}, 0, 0).',
        de: 'Hier ist det(a′, e, e′) = {k} und e × e′ = ({k}, 0, 0).',
      },
    ],
    solution: { answers: { delta: '(1 + a^2*u^2)/a' } },
  },
  {
    id: 'straight-striction',
    title: { en: 'A straight striction curve', de: 'Eine gerade Kehllinie' },
    prompt: {
      en: 'Type a ruled surface a(u) + v·e(u) whose striction curve is a straight line: the check measures the exact striction curve’s largest distance from its fitted line, as a share of the curve’s length (below 10⁻⁹).',
      de: 'Geben Sie eine Regelfläche a(u) + v·e(u) ein, deren Kehllinie eine Gerade ist: Die Prüfung misst den größten Abstand der exakten Kehllinie von ihrer Ausgleichsgeraden, bezogen auf die Länge der Kurve (unter 10⁻⁹).',
    },
    scene: 'formula',
    params: { preset: 'hyperboloid', tool: 'striction', exact: true },
    change: ['ax', 'ay', 'az', 'ex', 'ey', 'ez', 'umin', 'umax', 'a', 'b', 'c'],
    // (the menu of surfaces to start from names one whose striction curve is straight)
    hide: ['preset'],
    goal: [{ value: 'formula.strictionStraightness', below: 1e-9 }],
    hints: [
      {
        en: 'On a right helicoid every ruling meets the axis at a right angle.',
        de: 'Bei einer geraden Wendelfläche trifft jede Erzeugende die Achse rechtwinklig.',
      },
      {
        en: 'Try a(u) = (0, 0, u) and e(u) = (cos u, sin u, 0).',
        de: 'Versuchen Sie a(u) = (0, 0, u) und e(u) = (cos u, sin u, 0).',
      },
    ],
    solution: 'HELICOID',
  },
  {
    id: 'elliptic-congruence',
    title: { en: 'A congruence without real focal points', de: 'Eine Kongruenz ohne reelle Brennpunkte' },
    prompt: {
      en: 'A line of a congruence is hyperbolic when it carries two real focal points, elliptic when it carries none. Type a congruence p(u, v) + t·e(u, v) all of whose lines are elliptic.',
      de: 'Eine Gerade einer Geradenkongruenz ist hyperbolisch, wenn sie zwei reelle Brennpunkte trägt, elliptisch, wenn sie keinen trägt. Geben Sie eine Kongruenz p(u, v) + t·e(u, v) ein, deren Geraden alle elliptisch sind.',
    },
    scene: 'formula-congruence',
    params: { preset: 'example5', focal: true },
    change: ['px', 'py', 'pz', 'ex', 'ey', 'ez', 'umin', 'umax', 'vmin', 'vmax', 'a', 'b', 'c'],
    hide: ['focal', 'preset'],
    goal: [{ value: 'focal.ellipticShare', near: 1, within: 1e-9 }],
    hints: [
      {
        en: 'The focal points of a line are where it meets its infinitely near neighbours; they are real exactly when its two torsal directions are real.',
        de: 'Die Brennpunkte einer Geraden sind ihre Schnittpunkte mit den unendlich benachbarten Geraden; sie sind genau dann reell, wenn ihre beiden Torsalrichtungen reell sind.',
      },
      {
        en: 'Try the lines through the points (u, v, 0) with directions (−v, u, 1).',
        de: 'Versuchen Sie die Geraden durch die Punkte (u, v, 0) mit den Richtungen (−v, u, 1).',
      },
    ],
    solution: 'ELLIPTIC',
  },
  {
    id: 'line-space-slide',
    title: { en: 'Slide without turning', de: 'Verschieben ohne Drehen' },
    prompt: {
      en: 'The line-space scheme refines the lines; the endpoint scheme refines their endpoints. Slide given endpoints along their own rulings (the ⤡ mode of the ✎ bar): make the endpoint scheme’s new rulings turn by more than 0.05 rad while the line-space scheme’s do not turn (less than 10⁻⁹ rad).',
      de: 'Das Geradenraumschema verfeinert die Geraden, das Endpunktschema ihre Endpunkte. Verschieben Sie gegebene Endpunkte längs ihrer eigenen Erzeugenden (die Art ⤡ der ✎-Leiste): Die neuen Erzeugenden des Endpunktschemas sollen sich um mehr als 0,05 rad drehen, die des Geradenraumschemas sich nicht drehen (weniger als 10⁻⁹ rad).',
    },
    scene: 'lines',
    params: { surface: 'helical', slide: 0, steps: 2 },
    change: ['handles'],
    goal: [
      { value: 'lines.readout.endpoints', above: 0.05 },
      { value: 'lines.readout.lines', below: 1e-9 },
    ],
    hints: [
      {
        en: 'Press ✎ and choose ⤡ (along its line), then drag an end (with a mouse, Shift while dragging does the same): the end moves along its own ruling, whatever the view.',
        de: 'Tippen Sie auf ✎ und wählen Sie ⤡ (längs seiner Geraden), dann ziehen Sie ein Ende (mit der Maus tut Umschalt beim Ziehen dasselbe): Das Ende bewegt sich längs seiner eigenen Erzeugenden, unabhängig von der Ansicht.',
      },
      {
        en: 'A ruling whose ends only slide along it is the same line: the line-space scheme cannot tell the difference.',
        de: 'Eine Erzeugende, deren Enden nur auf ihr gleiten, bleibt dieselbe Gerade: Das Geradenraumschema merkt keinen Unterschied.',
      },
    ],
    solution: { input: LINES_SOLUTION },
  },
  {
    id: 'klein-torsal',
    title: { en: 'Find the torsal step by Ω', de: 'Den torsalen Schritt an Ω finden' },
    prompt: {
      en: 'On the Klein quadric each ruling is a point, and Ω(L_i, L_{i+1}) = −h sin φ of consecutive rulings is 0 exactly where they meet. The quartic surface of Example 3 has a torsal ruling, where its distribution parameter δ ≤ 0 touches 0. Which step i (between R_i and R_{i+1}) of its 24 rulings comes nearest to torsal? Read it off the polygon on M — its colour tells the sign of Ω — or scan the steps with the marked ruling, and type i (counted from 0).',
      de: 'Auf der Klein-Quadrik ist jede Erzeugende ein Punkt, und Ω(L_i, L_{i+1}) = −h sin φ aufeinanderfolgender Erzeugender ist genau dann 0, wenn sie sich schneiden. Die quartische Fläche von Beispiel 3 hat eine torsale Erzeugende, an der ihr Drall δ ≤ 0 die Null berührt. Welcher Schritt i (zwischen R_i und R_{i+1}) ihrer 24 Erzeugenden kommt einem torsalen am nächsten? Lesen Sie ihn am Polygon auf M ab – seine Farbe zeigt das Vorzeichen von Ω – oder gehen Sie die Schritte mit der markierten Erzeugenden durch, und geben Sie i ein (von 0 an gezählt).',
    },
    scene: 'klein',
    params: { surface: 'quartic', n: 24, conic: false },
    change: ['mix', 'turn', 'unit', 'space', 'mark'],
    answers: [{ id: 'step', kind: 'number', label: { en: 'step i', de: 'Schritt i' } }],
    goal: [{ answer: 'step', near: { value: 'klein.leastStep' }, within: 0.5 }],
    hints: [
      {
        en: 'Away from the torsal ruling δ < 0, so Ω = −h sin φ ≈ −δ φ² is positive: the polygon is blue. Near the torsal ruling |Ω| is tiny, and the discrete value may even change its sign.',
        de: 'Abseits der torsalen Erzeugenden ist δ < 0, also ist Ω = −h sin φ ≈ −δ φ² positiv: Das Polygon ist blau. Nahe der torsalen Erzeugenden ist |Ω| winzig, und der diskrete Wert kann sogar sein Vorzeichen wechseln.',
      },
      {
        en: 'The torsal ruling is at u = 0, the middle of the range [−1, 1]; 24 rulings have 23 steps, and the middle one is step 11, drawn orange and dashed: there Ω is −1.4·10⁻⁵.',
        de: 'Die torsale Erzeugende liegt bei u = 0, in der Mitte des Bereichs [−1, 1]; 24 Erzeugende haben 23 Schritte, der mittlere ist Schritt 11, orange und gestrichelt gezeichnet: Dort ist Ω = −1,4·10⁻⁵.',
      },
    ],
    solution: { answers: { step: 11 } },
  },
  {
    id: 'klein-conic',
    title: { en: 'Rulings on a conic of M', de: 'Erzeugende auf einem Kegelschnitt von M' },
    prompt: {
      en: 'Three lines, as points of the Klein quadric M, span a plane of P⁵, which in general cuts M in a conic. The rulings of a regulus — one family of a hyperboloid of one sheet or of a hyperbolic paraboloid — all lie on that conic. The helicoid’s do not: its rulings leave the plane of the first three by far. Choose a surface of the menu whose rulings lie on a conic of M: the largest distance of a ruling from the conic’s plane below 10⁻⁹.',
      de: 'Drei Geraden spannen als Punkte der Klein-Quadrik M eine Ebene des P⁵ auf, die M im Allgemeinen in einem Kegelschnitt schneidet. Die Erzeugenden einer Regelschar – einer Schar eines einschaligen Hyperboloids oder eines hyperbolischen Paraboloids – liegen alle auf diesem Kegelschnitt. Die der Wendelfläche nicht: Ihre Erzeugenden liegen weit außerhalb der Ebene der ersten drei. Wählen Sie eine Fläche des Menüs, deren Erzeugende auf einem Kegelschnitt von M liegen (größter Abstand einer Erzeugenden von der Ebene des Kegelschnitts kleiner als 10⁻⁹).',
    },
    scene: 'klein',
    params: { surface: 'helicoid', n: 24, conic: true },
    change: ['surface', 'mix', 'turn', 'unit', 'space', 'mark'],
    goal: [{ value: 'klein.readout.plane', below: 1e-9 }],
    hints: [
      {
        en: 'A regulus is a plane section of M; a surface whose rulings belong to a linear complex (a hyperplane section: the helicoid’s, whose residual is 0) need not be one.',
        de: 'Eine Regelschar ist ein ebener Schnitt von M; eine Fläche, deren Erzeugende einem linearen Komplex angehören (einem Hyperebenenschnitt: die der Wendelfläche, deren Residuum 0 ist), muss keine sein.',
      },
      {
        en: 'The hyperboloid and the hyperbolic paraboloid pass. So does the elliptic cone, in its own way: its rulings pass through one point, and the lines through a point fill a plane lying on M — the distance is 0, but that plane cuts out no conic (the cone’s rulings are a conic within it).',
        de: 'Das Hyperboloid und das hyperbolische Paraboloid bestehen. Auf eigene Weise auch der elliptische Kegel: Seine Erzeugenden gehen durch einen Punkt, und die Geraden durch einen Punkt füllen eine Ebene, die ganz auf M liegt – der Abstand ist 0, aber diese Ebene schneidet keinen Kegelschnitt aus (die Erzeugenden des Kegels sind ein Kegelschnitt in ihr).',
      },
    ],
    solution: { params: { surface: 'hyperbolic-paraboloid' } },
  },
  {
    id: 'klein-complex',
    title: { en: 'Move a line into the complex', de: 'Eine Gerade in den Komplex bringen' },
    prompt: {
      en: 'The tangents of a helix all lie in one linear complex: as points of the Klein quadric M they lie in one hyperplane section of M. Here the end b of ruling R_5 has been lifted, and the eight lines lie in no complex any more: the best one misses them by the residual in the readout. Move an end of R_5 — drag it (✎; ↕ moves it along z) or type its coordinates — until the rulings lie in a linear complex again: the largest |Ω(C, L_i)| for the best complex C below 0.005.',
      de: 'Die Tangenten einer Schraublinie liegen alle in einem linearen Komplex: Als Punkte der Klein-Quadrik M liegen sie in einem Hyperebenenschnitt von M. Hier wurde das Ende b der Erzeugenden R_5 angehoben, und die acht Geraden liegen in keinem Komplex mehr: Der beste verfehlt sie um das Residuum in den Messwerten. Bewegen Sie ein Ende von R_5 – ziehen Sie es (✎; ↕ bewegt es längs z) oder geben Sie seine Koordinaten ein –, bis die Erzeugenden wieder in einem linearen Komplex liegen: das größte |Ω(C, L_i)| für den besten Komplex C unter 0,005.',
    },
    scene: 'klein',
    params: { surface: 'helix-tangent', n: 8, conic: false, space: true, mark: 5 },
    input: COMPLEX_START,
    change: ['handles', 'mix', 'turn', 'unit', 'mark'],
    goal: [{ value: 'klein.readout.complex', below: 0.005 }],
    hints: [
      {
        en: 'The tangents of the helix (cos t, sin t, 0.3 t) lie in the null complex of a screw about its axis — not the helix’s own screw, but the one of pitch −1/0.3 (the opposite sense), whose null plane at each point of the helix is the osculating plane there. Turned about the axis, or moved along it, a ruling stays in that complex; an end lifted alone takes it out.',
        de: 'Die Tangenten der Schraublinie (cos t, sin t, 0,3 t) liegen im Nullkomplex einer Schraubung um ihre Achse – nicht der eigenen Schraubung der Schraublinie, sondern der mit dem Parameter −1/0,3 (im Gegensinn), deren Nullebene in jedem Punkt der Schraublinie deren Schmiegebene ist. Um die Achse gedreht oder längs der Achse verschoben, bleibt eine Erzeugende in diesem Komplex; ein Ende allein angehoben nimmt sie heraus.',
      },
      {
        en: 'The end b of R_5 was lifted by 0.3 along z. Tap it (where ends lie close together, a list names each) and type its z lower by 0.3; or choose ↕ in the ✎ bar and drag it down, after a long press for a fine drag, until the residual is below 0.005.',
        de: 'Das Ende b von R_5 wurde um 0,3 längs z angehoben. Tippen Sie es an (wo Enden dicht beieinander liegen, nennt eine Liste jedes) und geben Sie sein z um 0,3 kleiner ein; oder wählen Sie ↕ in der ✎-Leiste und ziehen Sie es nach unten, nach langem Drücken fein, bis das Residuum unter 0,005 liegt.',
      },
    ],
    solution: { input: COMPLEX_SOLUTION },
  },
];

/** An exercise of the list, its solution typed as a catalogue entry's formulas where it says so. */
function complete(/** @type {any} */ raw) {
  const solution =
    raw.solution === 'HELICOID'
      ? { params: pick(surfaceFields('helicoid'), ['ax', 'ay', 'az', 'ex', 'ey', 'ez', 'umin', 'umax']) }
      : raw.solution === 'ELLIPTIC'
        ? {
            params: pick(congruenceFields('elliptic'), [
              'px',
              'py',
              'pz',
              'ex',
              'ey',
              'ez',
              'umin',
              'umax',
              'vmin',
              'vmax',
            ]),
          }
        : raw.solution;
  return readTask({ ruledlab: 'exercise', version: 1, ...raw, solution });
}

/** @type {import('./format.js').Task[] | null} */
let tasks = null;

/** The built-in exercises, in the order of the paper (made once, when first asked for). */
export function builtInTasks() {
  tasks ??= RAW.map(complete);
  return tasks;
}

/** A built-in exercise by its id, or null. */
export function builtInTask(/** @type {string} */ id) {
  return builtInTasks().find((t) => t.id === id) ?? null;
}
