<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR" sourcelanguage="en">
<context>
    <name></name>
    <message>
        <source>valence %1, %2, %3</source>
        <translation type="vanished">valence %1, %2, %3</translation>
    </message>
    <message>
        <source>on the boundary</source>
        <translation type="vanished">sur le bord</translation>
    </message>
    <message>
        <source>interior</source>
        <translation type="vanished">intérieur</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the net of the vertex&apos;s piece).</source>
        <translation type="vanished">Matrice de subdivision locale S&#xa0;: %1 × %1 (le réseau du morceau du sommet).</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the vertex and every point within two faces of it).</source>
        <translation type="vanished">Matrice de subdivision locale S&#xa0;: %1 × %1 (le sommet et tous les points situés à deux faces au plus de celui-ci).</translation>
    </message>
    <message>
        <source>λ₁ = 1, λ = %1, μ = %2, λ² = %3</source>
        <translation type="vanished">λ₁ = 1, λ = %1, μ = %2, λ² = %3</translation>
    </message>
    <message>
        <source> (λ in closed form: %1)</source>
        <translation type="vanished"> (λ sous forme close&#xa0;: %1)</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for interior vertices only: a boundary vertex follows the crease rules, whose analysis needs the boundary&apos;s own characteristic map.</source>
        <translation type="vanished">Le critère de Reif n’est évalué ici que pour les sommets intérieurs&#xa0;: un sommet de bord suit les règles d’arête vive, dont l’analyse demande l’application caractéristique propre au bord.</translation>
    </message>
    <message>
        <source>spectral condition 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ real</source>
        <translation type="vanished">condition spectrale 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ réel</translation>
    </message>
    <message>
        <source>characteristic map regular: the Jacobian keeps one sign on all %1 cells (signed areas %2 … %3)</source>
        <translation type="vanished">application caractéristique régulière&#xa0;: le jacobien garde un signe constant sur les %1 cellules (aires signées %2 … %3)</translation>
    </message>
    <message>
        <source>characteristic map not regular: signed areas from %1 to %2</source>
        <translation type="vanished">application caractéristique non régulière&#xa0;: aires signées de %1 à %2</translation>
    </message>
    <message>
        <source>characteristic map injective: its boundary winds %1 time(s) around the vertex</source>
        <translation type="vanished">application caractéristique injective&#xa0;: son bord fait %1 tour(s) autour du sommet</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): the limit surface is C¹ at the vertex (for generic data).</source>
        <translation type="vanished">Verdict (Reif 1995)&#xa0;: la surface limite est C¹ au sommet (pour des données génériques).</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): C¹ is not established at the vertex.</source>
        <translation type="vanished">Verdict (Reif 1995)&#xa0;: la régularité C¹ au sommet n’est pas établie.</translation>
    </message>
    <message>
        <source>μ &lt; λ²: the curvature is zero at the vertex (the surface is flat there to second order, for generic data: no convex or saddle shape can be modelled at it)</source>
        <translation type="vanished">μ &lt; λ²&#xa0;: la courbure est nulle au sommet (pour des données génériques, la surface y est plate au second ordre&#xa0;: aucune forme convexe ou en selle ne peut y être modélisée)</translation>
    </message>
    <message>
        <source>μ = λ²: the curvature is bounded at the vertex</source>
        <translation type="vanished">μ = λ²&#xa0;: la courbure est bornée au sommet</translation>
    </message>
    <message>
        <source>μ &gt; λ²: the curvature is unbounded at the vertex (for generic data)</source>
        <translation type="vanished">μ &gt; λ²&#xa0;: la courbure n’est pas bornée au sommet (pour des données génériques)</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3), normal (%4, %5, %6).</source>
        <translation type="vanished">Position limite (%1, %2, %3), normale (%4, %5, %6).</translation>
    </message>
</context>
<context>
    <name>ExportDialog</name>
    <message>
        <source>Export Figure</source>
        <translation>Exporter la figure</translation>
    </message>
    <message>
        <source>&amp;View:</source>
        <translation>&amp;Vue&#xa0;:</translation>
    </message>
    <message>
        <source>The view or figure to export.</source>
        <translation>La vue ou la figure à exporter.</translation>
    </message>
    <message>
        <source>Attractor view</source>
        <translation>Vue de l’attracteur</translation>
    </message>
    <message>
        <source>Spectrum plot</source>
        <translation>Graphique du spectre</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>Matrices</translation>
    </message>
    <message>
        <source>Analysis chart (current tab)</source>
        <translation>Graphique d’analyse (onglet courant)</translation>
    </message>
    <message>
        <source>Figure sheet</source>
        <translation>Fiche de figure</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Fichier&#xa0;:</translation>
    </message>
    <message>
        <source>File to write; its suffix (.png, .svg or .pdf; .tex for the matrices as LaTeX) picks the format.</source>
        <translation>Fichier à écrire&#x202f;; son suffixe (.png, .svg ou .pdf&#x202f;; .tex pour les matrices en LaTeX) détermine le format.</translation>
    </message>
    <message>
        <source>Choose the file to write.</source>
        <translation>Choisir le fichier à écrire.</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Parcourir…</translation>
    </message>
    <message>
        <source>The suffix picks the format: .png, .svg or .pdf (the Matrices view also .tex: LaTeX bmatrix).</source>
        <translation>Le suffixe détermine le format&#xa0;: .png, .svg ou .pdf (la vue Matrices accepte aussi .tex&#xa0;: bmatrix LaTeX).</translation>
    </message>
    <message>
        <source>&amp;Width:</source>
        <translation>&amp;Largeur&#xa0;:</translation>
    </message>
    <message>
        <source>Width of the figure in pixels (for SVG and PDF: pixel units at the resolution below).</source>
        <translation>Largeur de la figure en pixels (pour SVG et PDF&#xa0;: unités de pixel à la résolution ci-dessous).</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>&amp;Height:</source>
        <translation>&amp;Hauteur&#xa0;:</translation>
    </message>
    <message>
        <source>Height of the figure in pixels (for SVG and PDF: pixel units at the resolution below).</source>
        <translation>Hauteur de la figure en pixels (pour SVG et PDF&#xa0;: unités de pixel à la résolution ci-dessous).</translation>
    </message>
    <message>
        <source>&amp;Resolution:</source>
        <translation>&amp;Résolution&#xa0;:</translation>
    </message>
    <message>
        <source>Resolution in dots per inch (dpi).</source>
        <translation>Résolution en points par pouce (ppp).</translation>
    </message>
    <message>
        <source> dpi</source>
        <translation> ppp</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>Afficher&#xa0;:</translation>
    </message>
    <message>
        <source>Draw the coordinate grid and its labels (when the view shows them).</source>
        <translation>Tracer la grille de coordonnées et ses étiquettes (lorsque la vue les affiche).</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>&amp;Grille</translation>
    </message>
    <message>
        <source>Draw the control polygons, the start set and their points and labels.</source>
        <translation>Tracer les polygones de contrôle, l’ensemble initial, ainsi que leurs points et leurs étiquettes.</translation>
    </message>
    <message>
        <source>&amp;Control points</source>
        <translation>&amp;Points de contrôle</translation>
    </message>
    <message>
        <source>Frame the attractor view&apos;s content tightly: the height follows the content&apos;s proportions (the width is kept).</source>
        <translation>Cadrer au plus près le contenu de la vue de l’attracteur&#xa0;: la hauteur suit les proportions du contenu (la largeur est conservée).</translation>
    </message>
    <message>
        <source>C&amp;rop to contents</source>
        <translation>Rogner au &amp;contenu</translation>
    </message>
    <message>
        <source>F&amp;ont:</source>
        <translation>P&amp;olice&#xa0;:</translation>
    </message>
    <message>
        <source>Font of the labels and of the figure sheet&apos;s text.</source>
        <translation>Police des étiquettes et du texte de la fiche de figure.</translation>
    </message>
    <message>
        <source>Label size in points as the figure is shown at its resolution (0: as on screen).</source>
        <translation>Taille des étiquettes en points, la figure étant affichée à sa résolution (0&#xa0;: comme à l’écran).</translation>
    </message>
    <message>
        <source>as on screen</source>
        <translation>comme à l’écran</translation>
    </message>
    <message>
        <source> pt</source>
        <translation> pt</translation>
    </message>
</context>
<context>
    <name>PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Préférences</translation>
    </message>
    <message>
        <source>Default &amp;depth of new items:</source>
        <translation>&amp;Profondeur par défaut des nouveaux éléments&#xa0;:</translation>
    </message>
    <message>
        <source>Deterministic depth given to new items.</source>
        <translation>Profondeur déterministe attribuée aux nouveaux éléments.</translation>
    </message>
    <message>
        <source>&amp;Maximum drawn depth:</source>
        <translation>Profondeur &amp;maximale tracée&#xa0;:</translation>
    </message>
    <message>
        <source>Draw at most this depth, whatever the item asks for.</source>
        <translation>Ne jamais tracer au-delà de cette profondeur, quelle que soit celle demandée par l’élément.</translation>
    </message>
    <message>
        <source>no limit</source>
        <translation>aucune limite</translation>
    </message>
    <message>
        <source>Map &amp;colours:</source>
        <translation>&amp;Couleurs des applications&#xa0;:</translation>
    </message>
    <message>
        <source>Colour of map 1</source>
        <translation>Couleur de l’application 1</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>Colour of map 2</source>
        <translation>Couleur de l’application 2</translation>
    </message>
    <message>
        <source>Colour of map 3</source>
        <translation>Couleur de l’application 3</translation>
    </message>
    <message>
        <source>Colour of map 4</source>
        <translation>Couleur de l’application 4</translation>
    </message>
    <message>
        <source>Colour of map 5</source>
        <translation>Couleur de l’application 5</translation>
    </message>
    <message>
        <source>Colour of map 6</source>
        <translation>Couleur de l’application 6</translation>
    </message>
    <message>
        <source>Use the views&apos; default colours for all maps.</source>
        <translation>Utiliser les couleurs par défaut des vues pour toutes les applications.</translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation>Valeurs par défaut</translation>
    </message>
    <message>
        <source>&amp;Autosave interval:</source>
        <translation>Intervalle d’enregistrement &amp;automatique&#xa0;:</translation>
    </message>
    <message>
        <source>Time between automatic saves of a recovery copy of the project, in seconds.</source>
        <translation>Durée entre deux enregistrements automatiques d’une copie de récupération du projet, en secondes.</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Dask &amp;scheduler:</source>
        <translation>&amp;Ordonnanceur Dask :</translation>
    </message>
    <message>
        <source>The address of a running Dask scheduler (tcp://host:8786) on which the Regularity Atlas computes; empty: a local cluster of this machine&apos;s cores.</source>
        <translation>L&apos;adresse d&apos;un ordonnanceur Dask en cours d&apos;exécution (tcp://host:8786) sur lequel l&apos;Atlas de régularité effectue ses calculs ; vide : un cluster local utilisant les cœurs de cette machine.</translation>
    </message>
    <message>
        <source>a local cluster of this machine</source>
        <translation>un cluster local de cette machine</translation>
    </message>
    <message>
        <source>&amp;Local workers:</source>
        <translation>Processus de calcul &amp;locaux :</translation>
    </message>
    <message>
        <source>Worker processes of the local Dask cluster (the Regularity Atlas without a scheduler address).</source>
        <translation>Processus de calcul du cluster Dask local (l&apos;Atlas de régularité sans adresse d&apos;ordonnanceur).</translation>
    </message>
    <message>
        <source>one per core</source>
        <translation>un par cœur</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>%1, Hölder regularity r in [%2, %3] (width %4)</source>
        <translation>%1, régularité höldérienne r dans [%2, %3] (largeur %4)</translation>
    </message>
    <message>
        <source>%1, Hölder regularity r = %2 (exact)</source>
        <translation>%1, régularité höldérienne r = %2 (exacte)</translation>
    </message>
    <message>
        <source>%1, Hölder regularity r = %2 (exact: invariant polytope, certificate)</source>
        <translation>%1, régularité de Hölder r = %2 (exacte&#xa0;: polytope invariant, certificat)</translation>
    </message>
    <message>
        <source>; Sobolev (L²) exponent s₂ = %1</source>
        <translation>&#xa0;; exposant de Sobolev (L²) s₂ = %1</translation>
    </message>
</context>
<context>
    <name>awb</name>
    <message>
        <source>the SVG does not parse: %1 (line %2, column %3)</source>
        <translation>le SVG ne se lit pas : %1 (ligne %2, colonne %3)</translation>
    </message>
    <message>
        <source>%1: cannot read the figure: %2</source>
        <translation>%1 : impossible de lire la figure : %2</translation>
    </message>
    <message>
        <source>larger than 512 MB</source>
        <translation>plus de 512 Mo</translation>
    </message>
    <message>
        <source>neither a PNG nor an SVG</source>
        <translation>ni un PNG ni un SVG</translation>
    </message>
    <message>
        <source>its project is larger than 64 MB</source>
        <translation>son projet dépasse 64 Mo</translation>
    </message>
    <message>
        <source>%1: this %2 holds no Attractor Workbench item (only figures exported by Attractor Workbench carry their parameters)</source>
        <translation>%1 : ce %2 ne contient aucun élément Attractor Workbench (seules les figures exportées par Attractor Workbench portent leurs paramètres)</translation>
    </message>
</context>
<context>
    <name>awb::AddressPanel</name>
    <message>
        <source>Address 0,1,1 or interval [0.25, 0.5]</source>
        <translation>Adresse 0,1,1 ou intervalle [0.25, 0.5]</translation>
    </message>
    <message>
        <source>An address selects the sub-copy f_w(A) = f_w1(f_w2(…(A))): map numbers from 0, the outermost map first. A subdivision curve also takes a parameter interval [t0, t1]. Enter selects, an empty field clears.</source>
        <translation>Une adresse sélectionne la sous-copie f_w(A) = f_w1(f_w2(…(A)))&#xa0;: les applications sont numérotées à partir de 0, la plus extérieure en premier. Une courbe de subdivision accepte aussi un intervalle de paramètre [t0, t1]. Entrée valide la sélection, un champ vide l’efface.</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Effacer</translation>
    </message>
    <message>
        <source>Click the attractor to pick an address; click a symbol of it to select that prefix.</source>
        <translation>Cliquez sur l’attracteur pour choisir une adresse&#x202f;; cliquez sur l’un de ses symboles pour sélectionner le préfixe correspondant.</translation>
    </message>
    <message>
        <source>address %1</source>
        <translation>adresse %1</translation>
    </message>
    <message>
        <source>, t ≈ %1</source>
        <translation>, t ≈ %1</translation>
    </message>
    <message>
        <source>Clicked: %1&lt;br&gt;&lt;small&gt;click a symbol to select the prefix up to it&lt;/small&gt;</source>
        <translation>Clic&#xa0;: %1&lt;br&gt;&lt;small&gt;cliquez sur un symbole pour sélectionner le préfixe qui s’arrête à lui&lt;/small&gt;</translation>
    </message>
    <message>
        <source>The item drawn has no addresses to select (only items drawn by one IFS in the plane have).</source>
        <translation>L’élément tracé n’a pas d’adresses à sélectionner (seuls les éléments tracés par un seul IFS du plan en ont).</translation>
    </message>
    <message>
        <source>a parameter interval selects on a subdivision curve with a real parameter; this item has none</source>
        <translation>un intervalle de paramètre ne sélectionne que sur une courbe de subdivision à paramètre réel&#x202f;; cet élément n’en a pas</translation>
    </message>
    <message>
        <source>t in %1</source>
        <translation>t dans %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;t in %1&lt;/b&gt; (%2)&lt;br&gt;Pieces inside it (addresses up to 8 symbols): %3</source>
        <translation>&lt;b&gt;t dans %1&lt;/b&gt; (%2)&lt;br&gt;Morceaux contenus dans l’intervalle (adresses d’au plus 8 symboles)&#xa0;: %3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>&lt;br&gt;The control polygons of the first %1 pieces are drawn.</source>
        <translation>&lt;br&gt;Les polygones de contrôle des %1 premiers morceaux sont tracés.</translation>
    </message>
    <message>
        <source>w = %1</source>
        <translation>w = %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;w = %1&lt;/b&gt;: the sub-copy f_w(A) = %2(A)</source>
        <translation>&lt;b&gt;w = %1&lt;/b&gt;&#xa0;: la sous-copie f_w(A) = %2(A)</translation>
    </message>
    <message>
        <source>   t in [%1, %2]</source>
        <translation>   t dans [%1, %2]</translation>
    </message>
    <message>
        <source>&lt;br&gt;t in [%1, %2] (%3)</source>
        <translation>&lt;br&gt;t dans [%1, %2] (%3)</translation>
    </message>
    <message>
        <source>&lt;br&gt;Control points S_w P = %1 (symbol i is S_(i+1)):&lt;br&gt;%2</source>
        <translation>&lt;br&gt;Points de contrôle S_w P = %1 (le symbole i désigne S_(i+1))&#xa0;:&lt;br&gt;%2</translation>
    </message>
</context>
<context>
    <name>awb::AlgorithmSpec</name>
    <message>
        <source>the depth cannot be negative, got %1</source>
        <translation>la profondeur ne peut pas être négative (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>depth %1 is absurd: at most %2 is allowed</source>
        <translation>une profondeur de %1 est absurde&#xa0;: %2 au maximum</translation>
    </message>
    <message>
        <source>the sample count must be between 1 and 2^31, got %1</source>
        <translation>le nombre d’échantillons doit être compris entre 1 et 2^31 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the seed must be between 0 and 2^53 - 1, got %1</source>
        <translation>la graine doit être comprise entre 0 et 2^53 - 1 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>probability %1 must be a finite number &gt;= 0</source>
        <translation>la probabilité %1 doit être un nombre fini &gt;= 0</translation>
    </message>
    <message>
        <source>the probabilities sum to 0</source>
        <translation>la somme des probabilités est nulle</translation>
    </message>
    <message>
        <source>depth %1 with %2 maps makes %3 images of the start set, more than 2^31: at most depth %4 for %2 maps</source>
        <translation>la profondeur %1 avec %2 applications donne %3 images de l’ensemble initial, plus que 2^31 : au plus la profondeur %4 pour %2 applications</translation>
    </message>
</context>
<context>
    <name>awb::AnalysisCharts</name>
    <message>
        <source>Distance to the exact curve</source>
        <translation>Distance à la courbe exacte</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>Distance</translation>
    </message>
    <message>
        <source>Control polygon length</source>
        <translation>Longueur du polygone de contrôle</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Longueur</translation>
    </message>
    <message>
        <source>Box counting</source>
        <translation>Comptage de boîtes</translation>
    </message>
    <message>
        <source>Eigenvalue moduli</source>
        <translation>Modules des valeurs propres</translation>
    </message>
    <message>
        <source>|λ| per map</source>
        <translation>|λ| par application</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;depth k = %2&lt;br&gt;d&lt;sub&gt;H&lt;/sub&gt; = %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;profondeur k = %2&lt;br&gt;d&lt;sub&gt;H&lt;/sub&gt; = %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;step k = %2&lt;br&gt;length = %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;étape k = %2&lt;br&gt;longueur = %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;log(1/ε) = %2 (ε = %3)&lt;br&gt;log N(ε) = %4 (N = %5)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;log(1/ε) = %2 (ε = %3)&lt;br&gt;log N(ε) = %4 (N = %5)</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;|λ| = %2</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;|λ| = %2</translation>
    </message>
    <message>
        <source>depth k</source>
        <translation>profondeur k</translation>
    </message>
    <message>
        <source>Hausdorff distance</source>
        <translation>distance de Hausdorff</translation>
    </message>
    <message>
        <source>control polygon</source>
        <translation>polygone de contrôle</translation>
    </message>
    <message>
        <source>exact curve</source>
        <translation>courbe exacte</translation>
    </message>
    <message>
        <source>subdivision step k</source>
        <translation>étape de subdivision k</translation>
    </message>
    <message>
        <source>length</source>
        <translation>longueur</translation>
    </message>
    <message>
        <source>Box counting: no fit (%1)</source>
        <translation>Comptage de boîtes&#xa0;: pas d’ajustement (%1)</translation>
    </message>
    <message>
        <source>not fitted</source>
        <translation>non ajusté</translation>
    </message>
    <message>
        <source>fitted levels</source>
        <translation>niveaux ajustés</translation>
    </message>
    <message>
        <source>log(1/ε)</source>
        <translation>log(1/ε)</translation>
    </message>
    <message>
        <source>log N(ε)</source>
        <translation>log N(ε)</translation>
    </message>
    <message>
        <source>map</source>
        <translation>application</translation>
    </message>
    <message>
        <source>|λ| = 1</source>
        <translation>|λ| = 1</translation>
    </message>
    <message>
        <source>|λ|</source>
        <translation>|λ|</translation>
    </message>
    <message>
        <source>No exact curve known for this item</source>
        <translation>Aucune courbe exacte connue pour cet élément</translation>
    </message>
    <message>
        <source>The Hausdorff distance is measured against an exact curve: B-spline, Bézier and complex de Casteljau curves have one.</source>
        <translation>La distance de Hausdorff est mesurée par rapport à une courbe exacte&#xa0;: les B-splines, les courbes de Bézier et les courbes de de Casteljau complexes en ont une.</translation>
    </message>
    <message>
        <source>∝ (%1)ᵏ</source>
        <translation>∝ (%1)ᵏ</translation>
    </message>
    <message>
        <source>D = %1 (R² = %2)</source>
        <translation>D = %1 (R² = %2)</translation>
    </message>
    <message>
        <source>Box-counting dimension D = %1: the slope of log N(ε) against log(1/ε) over the fitted levels, log N = %1 log(1/ε) + %2, R² = %3</source>
        <translation>Dimension de comptage de boîtes D = %1 : la pente de log N(ε) en fonction de log(1/ε) sur les niveaux ajustés, log N = %1 log(1/ε) + %2, R² = %3</translation>
    </message>
    <message>
        <source>No fit</source>
        <translation>Pas d’ajustement</translation>
    </message>
    <message>
        <source>slope %1</source>
        <translation>pente %1</translation>
    </message>
</context>
<context>
    <name>awb::Animation</name>
    <message>
        <source>expected a duration in seconds above 0 and at most %1</source>
        <translation>durée en secondes attendue, strictement positive et d’au plus %1</translation>
    </message>
    <message>
        <source>expected between 1 and %1 frames per second</source>
        <translation>entre 1 et %1 images par seconde attendues</translation>
    </message>
    <message>
        <source>%1 s at %2 frames per second makes more than %3 frames</source>
        <translation>%1 s à %2 images par seconde donnent plus de %3 images</translation>
    </message>
    <message>
        <source>names no parameter</source>
        <translation>ne désigne aucun paramètre</translation>
    </message>
    <message>
        <source>%1 is driven by an earlier track already</source>
        <translation>%1 est déjà piloté par une piste précédente</translation>
    </message>
    <message>
        <source>needs at least one key</source>
        <translation>il faut au moins une clé</translation>
    </message>
    <message>
        <source>expected a time between 0 and the duration, %1 s</source>
        <translation>instant attendu entre 0 et la durée, %1 s</translation>
    </message>
    <message>
        <source>key times must increase (%1 s follows %2 s)</source>
        <translation>les instants des clés doivent être croissants (%1 s suit %2 s)</translation>
    </message>
    <message>
        <source>expected %1 numbers, as the first key</source>
        <translation>%1 nombres attendus, comme pour la première clé</translation>
    </message>
    <message>
        <source>not a finite number</source>
        <translation>n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>a circle turns a point or a complex value, not one number</source>
        <translation>un cercle fait tourner un point ou une valeur complexe, pas un nombre seul</translation>
    </message>
    <message>
        <source>expected [x, y]</source>
        <translation>[x, y] attendu</translation>
    </message>
    <message>
        <source>expected a number of turns between -1000 and 1000</source>
        <translation>nombre de tours attendu entre -1000 et 1000</translation>
    </message>
    <message>
        <source>Probabilities</source>
        <translation>Probabilités</translation>
    </message>
    <message>
        <source>Points %1, point %2</source>
        <translation>Ensemble de points %1, point %2</translation>
    </message>
    <message>
        <source>Control point %1</source>
        <translation>Point de contrôle %1</translation>
    </message>
    <message>
        <source>%1 has no probabilities</source>
        <translation>%1 n’a pas de probabilités</translation>
    </message>
    <message>
        <source>%1 has no control point %2 in point set %3</source>
        <translation>%1 n’a pas de point de contrôle %2 dans l’ensemble de points %3</translation>
    </message>
    <message>
        <source>%1 is not a number that can be animated</source>
        <translation>%1 n’est pas un nombre animable</translation>
    </message>
    <message>
        <source>%1 has no parameter %2 (now)</source>
        <translation>%1 n’a pas de paramètre %2 (dans son état actuel)</translation>
    </message>
    <message>
        <source>no such control point</source>
        <translation>point de contrôle inexistant</translation>
    </message>
    <message>
        <source>the point was refused</source>
        <translation>le point a été refusé</translation>
    </message>
    <message>
        <source>no such parameter now</source>
        <translation>ce paramètre n’existe pas actuellement</translation>
    </message>
    <message>
        <source>a complex value needs 2 numbers</source>
        <translation>une valeur complexe demande 2 nombres</translation>
    </message>
    <message>
        <source>%1 at %2 s: %3</source>
        <translation>%1 à %2 s&#xa0;: %3</translation>
    </message>
    <message>
        <source>the value was refused</source>
        <translation>la valeur a été refusée</translation>
    </message>
    <message>
        <source>%1 has %2 coordinates, the keys %3</source>
        <translation>%1 a %2 coordonnées, les clés en ont %3</translation>
    </message>
    <message>
        <source>p = (%1)</source>
        <translation>p = (%1)</translation>
    </message>
    <message>
        <source>t = %1 s: %2</source>
        <translation>t = %1 s&#xa0;: %2</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>manquant</translation>
    </message>
    <message>
        <source>expected an array of tracks</source>
        <translation>tableau de pistes attendu</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>objet attendu</translation>
    </message>
    <message>
        <source>expected an array of keys</source>
        <translation>tableau de clés attendu</translation>
    </message>
    <message>
        <source>expected an object {&quot;time&quot;, &quot;value&quot;}</source>
        <translation>objet {&quot;time&quot;, &quot;value&quot;} attendu</translation>
    </message>
    <message>
        <source>unknown field of a key</source>
        <translation>champ inconnu dans une clé</translation>
    </message>
    <message>
        <source>unknown field of a track</source>
        <translation>champ inconnu dans une piste</translation>
    </message>
    <message>
        <source>unknown field of an animation</source>
        <translation>champ inconnu dans une animation</translation>
    </message>
</context>
<context>
    <name>awb::AnimationPanel</name>
    <message>
        <source>Play / pause the animation (Ctrl+Space)</source>
        <translation>Lire / mettre en pause l’animation (Ctrl+Space)</translation>
    </message>
    <message>
        <source>Stop: the views show the item itself again</source>
        <translation>Arrêter&#xa0;: les vues montrent de nouveau l’élément lui-même</translation>
    </message>
    <message>
        <source>Time: drag to see the frames (the views follow)</source>
        <translation>Temps&#xa0;: faites glisser pour parcourir les images (les vues suivent)</translation>
    </message>
    <message>
        <source>Time and frame number</source>
        <translation>Temps et numéro d’image</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>En boucle</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Lecture</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Duration of the animation</source>
        <translation>Durée de l’animation</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Images par seconde</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> i/s</translation>
    </message>
    <message>
        <source>Parameter / key time (s)</source>
        <translation>Paramètre / instant de la clé (s)</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valeur</translation>
    </message>
    <message>
        <source>Double-click a key&apos;s time or value to edit it</source>
        <translation>Double-cliquez sur l’instant ou la valeur d’une clé pour la modifier</translation>
    </message>
    <message>
        <source>The parameter, probabilities or control point to key</source>
        <translation>Le paramètre, les probabilités ou le point de contrôle sur lequel poser une clé</translation>
    </message>
    <message>
        <source>Set Key</source>
        <translation>Poser une clé</translation>
    </message>
    <message>
        <source>Store the item&apos;s present value of the parameter at the time shown (replaces a key at that time)</source>
        <translation>Enregistrer la valeur actuelle du paramètre de l’élément à l’instant affiché (remplace la clé existant à cet instant)</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Remove the selected key, or the selected track with its keys</source>
        <translation>Supprimer la clé sélectionnée, ou la piste sélectionnée avec ses clés</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linéaire</translation>
    </message>
    <message>
        <source>Smooth (ease in and out)</source>
        <translation>Adoucie (départ et arrivée progressifs)</translation>
    </message>
    <message>
        <source>Through the keys</source>
        <translation>Passant par les clés</translation>
    </message>
    <message>
        <source>Circle about a centre</source>
        <translation>Cercle autour d’un centre</translation>
    </message>
    <message>
        <source>x, y</source>
        <translation>x, y</translation>
    </message>
    <message>
        <source>Interpolation</source>
        <translation>Interpolation</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Trajectoire</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>Centre</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>Tours</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>The views show the item itself.</source>
        <translation>Les vues montrent l’élément lui-même.</translation>
    </message>
    <message>
        <source>%1 s · %2/%3</source>
        <translation>%1 s · %2/%3</translation>
    </message>
    <message>
        <source>Frame at %1 s: %2</source>
        <translation>Image à %1 s&#xa0;: %2</translation>
    </message>
    <message>
        <source>The views show the frame at %1 s (not editable); Stop returns to the item.</source>
        <translation>Les vues montrent l’image à %1 s (non modifiable)&#x202f;; Arrêter revient à l’élément.</translation>
    </message>
    <message>
        <source>No item is selected.</source>
        <translation>Aucun élément n’est sélectionné.</translation>
    </message>
    <message>
        <source>Select a key or a track to remove.</source>
        <translation>Sélectionnez une clé ou une piste à supprimer.</translation>
    </message>
    <message>
        <source>inactive: %1 has no such input now</source>
        <translation>inactive&#xa0;: %1 n’a pas cette entrée actuellement</translation>
    </message>
    <message>
        <source>circle about (%1), %2 turns</source>
        <translation>cercle autour de (%1), %2 tours</translation>
    </message>
    <message>
        <source>The item does not have %1 in its present state (another scheme, fewer points): the track is kept and skipped.</source>
        <translation>L’élément n’a pas %1 dans son état actuel (autre schéma, moins de points)&#xa0;: la piste est conservée mais ignorée.</translation>
    </message>
    <message>
        <source>Select an item to animate its parameters.</source>
        <translation>Sélectionnez un élément pour animer ses paramètres.</translation>
    </message>
    <message>
        <source>No keys yet: set a value in Properties, choose it here and press Set Key; then move the slider, change the value and key it again.</source>
        <translation>Pas encore de clés&#xa0;: réglez une valeur dans Propriétés, choisissez-la ici et cliquez sur Poser une clé&#x202f;; déplacez ensuite le curseur, modifiez la valeur et posez une nouvelle clé.</translation>
    </message>
    <message>
        <source>%1 has no numeric parameters to animate.</source>
        <translation>%1 n’a pas de paramètres numériques à animer.</translation>
    </message>
    <message>
        <source>%1 tracks, %2 frames. Play or drag the slider to preview.</source>
        <translation>%1 pistes, %2 images. Lancez la lecture ou faites glisser le curseur pour prévisualiser.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a time in seconds</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas un temps en secondes</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: expected %2 numbers</source>
        <translation>«&#xa0;%1&#xa0;»&#xa0;: %2 nombres attendus</translation>
    </message>
</context>
<context>
    <name>awb::AtlasPlot</name>
    <message>
        <source>upper bound on r</source>
        <translation>borne supérieure de r</translation>
    </message>
    <message>
        <source>lower bound on r (certified)</source>
        <translation>borne inférieure de r (certifiée)</translation>
    </message>
    <message>
        <source>Hölder exponent r</source>
        <translation>Exposant de Hölder r</translation>
    </message>
    <message>
        <source>Shaded: certified C&lt;sup&gt;%1&lt;/sup&gt; (lower bound &amp;gt; %1). %2 points.</source>
        <translation>Ombré : C&lt;sup&gt;%1&lt;/sup&gt; certifié (borne inférieure &amp;gt; %1). %2 points.</translation>
    </message>
    <message>
        <source>not certified C⁰</source>
        <translation>C⁰ non certifié</translation>
    </message>
    <message>
        <source>C⁰</source>
        <translation>C⁰</translation>
    </message>
    <message>
        <source>C¹</source>
        <translation>C¹</translation>
    </message>
    <message>
        <source>C²</source>
        <translation>C²</translation>
    </message>
    <message>
        <source>C³ or more</source>
        <translation>C³ ou plus</translation>
    </message>
    <message>
        <source>&lt;span style=&quot;color:#c83c14&quot;&gt;□&lt;/span&gt; the bounds cannot tell C&lt;sup&gt;%1&lt;/sup&gt;; white: no member. %2 points.</source>
        <translation>&lt;span style=&quot;color:#c83c14&quot;&gt;□&lt;/span&gt; les bornes ne permettent pas de trancher C&lt;sup&gt;%1&lt;/sup&gt; ; blanc : aucun membre. %2 points.</translation>
    </message>
    <message>
        <source>no member here: %1</source>
        <translation>aucun membre ici : %1</translation>
    </message>
    <message>
        <source>C^∞ (a polynomial piece)</source>
        <translation>C^∞ (un morceau polynomial)</translation>
    </message>
    <message>
        <source>Hölder exponent r in [%1, %2]%3</source>
        <translation>Exposant de Hölder r dans [%1, %2]%3</translation>
    </message>
    <message>
        <source>, exact (invariant polytope)</source>
        <translation>, exact (polytope invariant)</translation>
    </message>
    <message>
        <source>certified C^%1</source>
        <translation>C^%1 certifié</translation>
    </message>
    <message>
        <source>C^%1 as asked: yes</source>
        <translation>C^%1 demandé : oui</translation>
    </message>
    <message>
        <source>C^%1 as asked: certified no</source>
        <translation>C^%1 demandé : non (certifié)</translation>
    </message>
    <message>
        <source>C^%1 as asked: the bounds cannot tell</source>
        <translation>C^%1 demandé : les bornes ne permettent pas de trancher</translation>
    </message>
    <message>
        <source>Sobolev exponent s₂ = %1</source>
        <translation>Exposant de Sobolev s₂ = %1</translation>
    </message>
    <message>
        <source>stopped by the safety clock: may differ on another machine</source>
        <translation>arrêté par la limite de temps de sécurité : peut différer sur une autre machine</translation>
    </message>
    <message>
        <source>Click to add an item with these parameters.</source>
        <translation>Cliquez pour ajouter un élément avec ces paramètres.</translation>
    </message>
</context>
<context>
    <name>awb::AttractorItem</name>
    <message>
        <source>Change start set of %1</source>
        <translation>Modifier l’ensemble initial de %1</translation>
    </message>
    <message>
        <source>Change algorithm of %1</source>
        <translation>Modifier l’algorithme de %1</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n control points of %1</source>
        <translation>
            <numerusform>Supprimer %n point de contrôle de %1</numerusform>
            <numerusform>Supprimer %n points de contrôle de %1</numerusform>
        </translation>
    </message>
    <message>
        <source>map %1 is not finite: the control points&apos; coordinates overflow in the lifted map P⁻¹ S_i P (the largest is %2)</source>
        <translation>l’application %1 n’est pas finie&#xa0;: les coordonnées des points de contrôle provoquent un dépassement de capacité dans l’application relevée P⁻¹ S_i P (la plus grande vaut %2)</translation>
    </message>
    <message>
        <source>the start set is not finite in the IFS space: the lifting overflows (the largest control point coordinate is %1)</source>
        <translation>l’ensemble initial n’est pas fini dans l’espace de l’IFS&#xa0;: le relèvement provoque un dépassement de capacité (la plus grande coordonnée de point de contrôle vaut %1)</translation>
    </message>
    <message>
        <source>lifted start points need an invertible lifting: %1</source>
        <translation>des points initiaux relevés exigent un relèvement inversible&#xa0;: %1</translation>
    </message>
    <message>
        <source>a lifted start point of this item has %1 coordinates (x, y and the %2 extra coordinates of the lifting, the homogeneous 1 implied); point %3 has %4</source>
        <translation>un point initial relevé de cet élément a %1 coordonnées (x, y et les %2 coordonnées supplémentaires du relèvement, le 1 homogène étant implicite)&#x202f;; le point %3 en a %4</translation>
    </message>
    <message>
        <source>%1 points; an item takes at most %2 (its subdivision matrices would be %1 x %1)</source>
        <translation>%1 points&#x202f;; un élément en accepte au plus %2 (ses matrices de subdivision seraient de taille %1 x %1)</translation>
    </message>
    <message>
        <source>point set %1 has %2 points; an item takes at most %3 per set</source>
        <translation>l’ensemble de points %1 a %2 points&#x202f;; un élément en accepte au plus %3 par ensemble</translation>
    </message>
    <message>
        <source>the start set &quot;vertex-limits&quot; (the limit positions of a mesh&apos;s vertices) is for mesh items only; this item: %1</source>
        <translation>l’ensemble initial &quot;vertex-limits&quot; (les positions limites des sommets d’un maillage) est réservé aux éléments maillage&#x202f;; cet élément&#xa0;: %1</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Point</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation>Triangle</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Polygone</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Points</translation>
    </message>
    <message>
        <source>Lifted points</source>
        <translation>Points relevés</translation>
    </message>
    <message>
        <source>Vertex limits</source>
        <translation>Positions limites des sommets</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Start set X0</source>
        <translation>Ensemble initial X0</translation>
    </message>
    <message>
        <source>The set X0 deterministic iteration starts from; drag its vertices in the attractor view. Lifted points are points of the lifted space of 000 §2; vertex limits, a mesh&apos;s vertices&apos; limit positions.</source>
        <translation type="vanished">L’ensemble X0 dont part l’itération déterministe&#x202f;; faites glisser ses sommets dans la vue de l’attracteur. Les points relevés sont des points de l’espace relevé de 000 §2&#x202f;; les positions limites des sommets, celles des sommets d’un maillage.</translation>
    </message>
    <message>
        <source>The item has no control points.</source>
        <translation>L’élément n’a pas de points de contrôle.</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Sommets</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number.</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas un nombre.</translation>
    </message>
    <message>
        <source>Lifted</source>
        <translation>Relevés</translation>
    </message>
    <message>
        <source>Points of the lifted space of 000 §2: x, y, then the extra coordinates of the lifting, the homogeneous 1 implied. Commas between coordinates, &apos;;&apos; between points.</source>
        <translation>Points de l’espace relevé de 000 §2&#xa0;: x, y, puis les coordonnées supplémentaires du relèvement, le 1 homogène étant implicite. Des virgules entre les coordonnées, «&#x202f;;&#xa0;» entre les points.</translation>
    </message>
    <message>
        <source>Deterministic</source>
        <translation>Déterministe</translation>
    </message>
    <message>
        <source>Random (chaos game)</source>
        <translation>Aléatoire (jeu du chaos)</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <source>Algorithm</source>
        <translation>Algorithme</translation>
    </message>
    <message>
        <source>Deterministic iteration draws F^k(X0) at the depth k; random iteration plays the chaos game with the samples</source>
        <translation>L’itération déterministe trace F^k(X0) à la profondeur k&#x202f;; l’itération aléatoire joue au jeu du chaos avec les échantillons</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Profondeur</translation>
    </message>
    <message>
        <source>The level k of F^k(X0): N^k images of the start set, at most 2^31</source>
        <translation>Le niveau k de F^k(X0)&#xa0;: N^k images de l’ensemble initial, au plus 2^31</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>Échantillons</translation>
    </message>
    <message>
        <source>Points of the chaos game</source>
        <translation>Nombre de points du jeu du chaos</translation>
    </message>
    <message>
        <source>Probabilities</source>
        <translation>Probabilités</translation>
    </message>
    <message>
        <source>One weight per map for the chaos game; none: uniform</source>
        <translation>Un poids par application pour le jeu du chaos&#x202f;; aucun&#xa0;: uniforme</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Graine</translation>
    </message>
    <message>
        <source>The chaos game&apos;s random stream: the same seed, the same picture</source>
        <translation>Le flux aléatoire du jeu du chaos&#xa0;: même graine, même image</translation>
    </message>
    <message>
        <source>%1 has no point set %2</source>
        <translation>%1 n’a pas d’ensemble de points %2</translation>
    </message>
    <message>
        <source>%1: its scheme fixes the number of points at %2, got %3</source>
        <translation>%1&#xa0;: son schéma fixe le nombre de points à %2 (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>%1: %2 points is more than the %3 a point set may have</source>
        <translation>%1&#xa0;: %2 points, c’est plus que les %3 qu’un ensemble de points peut contenir</translation>
    </message>
    <message>
        <source>every point must have finite coordinates</source>
        <translation>tous les points doivent avoir des coordonnées finies</translation>
    </message>
    <message>
        <source>Set the points of %1</source>
        <translation>Définir les points de %1</translation>
    </message>
    <message>
        <source>the points of %1 were refused</source>
        <translation>les points de %1 ont été refusés</translation>
    </message>
    <message>
        <source>the start set &quot;net&quot; (control points of the net by index) is for items whose IFS is built from one control net (curves, surfaces, fractals with control points); this item: %1</source>
        <translation>l’ensemble initial « net » (points de contrôle du réseau par indice) est réservé aux éléments dont l’IFS est construit à partir d’un seul réseau de contrôle (courbes, surfaces, fractales à points de contrôle) ; cet élément : %1</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2; this item has %3 control points (indices 0 to %4)</source>
        <translation>le point de réseau %1 de l’ensemble initial a l’indice %2 ; cet élément a %3 points de contrôle (indices 0 à %4)</translation>
    </message>
    <message>
        <source>Net points</source>
        <translation>Points du réseau</translation>
    </message>
    <message>
        <source>The set X0 deterministic iteration starts from; drag its vertices in the attractor view. Lifted points are points of the lifted space of 000 §2; vertex limits, a mesh&apos;s vertices&apos; limit positions; net points, control points by index, which the set follows when they move.</source>
        <translation>L’ensemble X0 dont part l’itération déterministe ; faites glisser ses sommets dans la vue de l’attracteur. Les points relevés sont des points de l’espace relevé de 000 §2 ; les positions limites des sommets, celles des sommets d’un maillage ; les points du réseau, des points de contrôle par indice, que l’ensemble suit quand ils bougent.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a net point index (an integer from 0).</source>
        <translation type="vanished">« %1 » n’est pas un indice de point du réseau (un entier à partir de 0).</translation>
    </message>
    <message>
        <source>Control points by index, counted from 0 (commas between them): the start set is their point, segment or polygon in the lifted space, and it follows them when they move.</source>
        <translation>Points de contrôle par indice, comptés à partir de 0 (séparés par des virgules) : l’ensemble initial est leur point, leur segment ou leur polygone dans l’espace relevé, et il les suit quand ils bougent.</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2; the net has %3 points</source>
        <translation>le point de réseau %1 de l’ensemble initial a l’indice %2 ; le réseau a %3 points</translation>
    </message>
    <message>
        <source>this item has no control net to start from</source>
        <translation>cet élément n’a pas de réseau de contrôle dont partir</translation>
    </message>
</context>
<context>
    <name>awb::AttractorRenderer</name>
    <message>
        <source>Cannot draw the attractor: %1</source>
        <translation>Impossible de tracer l’attracteur&#xa0;: %1</translation>
    </message>
</context>
<context>
    <name>awb::AttractorView</name>
    <message>
        <source>Rendering… %1 %</source>
        <translation>Rendu… %1&#xa0;%</translation>
    </message>
    <message>
        <source>Rendering cancelled at %1 % — press F5 to render again</source>
        <translation>Rendu annulé à %1&#xa0;% — appuyez sur F5 pour relancer le rendu</translation>
    </message>
    <message>
        <source>F^%1(X₀) has too many images to draw as vectors</source>
        <translation>F^%1(X₀) a trop d’images pour être tracé sous forme vectorielle</translation>
    </message>
    <message>
        <source>there is no attractor to count</source>
        <translation>il n’y a pas d’attracteur à compter</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonAnalysis</name>
    <message>
        <source>every long path contracts</source>
        <translation>tout chemin long est contractant</translation>
    </message>
    <message>
        <source>some path does not contract</source>
        <translation>un chemin n&apos;est pas contractant</translation>
    </message>
    <message>
        <source>not decided</source>
        <translation>non décidé</translation>
    </message>
    <message>
        <source>constrained JSR ρ = %1 exactly (invariant polytope, extremal cycle %2): %3</source>
        <translation>rayon spectral joint contraint ρ = %1 exactement (polytope invariant, cycle extrémal %2) : %3</translation>
    </message>
    <message>
        <source>constrained JSR ρ in [%1, %2]: %3</source>
        <translation>rayon spectral joint contraint ρ dans [%1, %2] : %3</translation>
    </message>
    <message>
        <source>Lyapunov exponent of random iteration %1 (%2)</source>
        <translation>exposant de Lyapunov de l&apos;itération aléatoire %1 (%2)</translation>
    </message>
    <message>
        <source>contracts on average</source>
        <translation>contractant en moyenne</translation>
    </message>
    <message>
        <source>does not contract on average</source>
        <translation>non contractant en moyenne</translation>
    </message>
    <message>
        <source>cycle %1: ρ = %2 (%3 per arc); eigenvalues %4</source>
        <translation>cycle %1 : ρ = %2 (%3 par arc) ; valeurs propres %4</translation>
    </message>
    <message>
        <source>… and %1 more cycles</source>
        <translation>… et %1 cycles de plus</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonGraph</name>
    <message>
        <source>Automaton graph</source>
        <translation>Graphe de l&apos;automate</translation>
    </message>
    <message>
        <source>No states</source>
        <translation>Aucun état</translation>
    </message>
    <message>
        <source>%1 pts</source>
        <translation>%1 pts</translation>
    </message>
    <message>
        <source>State %1: %2 control points%3</source>
        <translation>État %1 : %2 points de contrôle%3</translation>
    </message>
    <message>
        <source>, drawn</source>
        <translation>, tracé</translation>
    </message>
    <message>
        <source>Arc %1: %2 → %3 (maps the space of %3 into %2)</source>
        <translation>Arc %1 : %2 → %3 (envoie l&apos;espace de %3 dans celui de %2)</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonPanel</name>
    <message>
        <source>Select a controlled IFS item to see and edit its automaton (Items &gt; Add &gt; Controlled IFS, or the example 003 Fig. 5).</source>
        <translation type="vanished">Sélectionnez un élément IFS contrôlé pour voir et modifier son automate (Éléments &gt; Ajouter &gt; IFS contrôlé, ou l&apos;exemple 003 Fig. 5).</translation>
    </message>
    <message>
        <source>Drawn:</source>
        <translation>Tracé :</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn, or the union of all</source>
        <translation>L&apos;état dont l&apos;attracteur est tracé, ou l&apos;union de tous</translation>
    </message>
    <message>
        <source>Add State</source>
        <translation>Ajouter un état</translation>
    </message>
    <message>
        <source> points</source>
        <translation> points</translation>
    </message>
    <message>
        <source>The new state&apos;s number of control points: the dimension of its barycentric space (3: a frame triangle)</source>
        <translation>Le nombre de points de contrôle du nouvel état : la dimension de son espace barycentrique (3 : un triangle de repère)</translation>
    </message>
    <message>
        <source>Remove State</source>
        <translation>Supprimer l&apos;état</translation>
    </message>
    <message>
        <source>Add Arc</source>
        <translation>Ajouter un arc</translation>
    </message>
    <message>
        <source>A new arc leaving the selected state (into itself; pick its target below)</source>
        <translation>Un nouvel arc partant de l&apos;état sélectionné (vers lui-même ; choisissez sa cible ci-dessous)</translation>
    </message>
    <message>
        <source>Remove Arc</source>
        <translation>Supprimer l&apos;arc</translation>
    </message>
    <message>
        <source>Click a state or an arc to edit it.</source>
        <translation>Cliquez sur un état ou un arc pour le modifier.</translation>
    </message>
    <message>
        <source>State name</source>
        <translation>Nom de l&apos;état</translation>
    </message>
    <message>
        <source>Arc name</source>
        <translation>Nom de l&apos;arc</translation>
    </message>
    <message>
        <source>From → to</source>
        <translation>De → à</translation>
    </message>
    <message>
        <source>The arc&apos;s relative probability among the arcs leaving its state (random iteration)</source>
        <translation>La probabilité relative de l&apos;arc parmi les arcs partant de son état (itération aléatoire)</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Poids</translation>
    </message>
    <message>
        <source>Matrix S (rows sum to 1)</source>
        <translation>Matrice S (lignes de somme 1)</translation>
    </message>
    <message>
        <source>Plane affine map</source>
        <translation>Application affine du plan</translation>
    </message>
    <message>
        <source>Piece of a curve scheme</source>
        <translation>Morceau d&apos;un schéma de courbe</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Application</translation>
    </message>
    <message>
        <source>S: a row per control point of the target state, a column per control point of the source; numbers like 1/3 are read exactly</source>
        <translation>S : une ligne par point de contrôle de l&apos;état cible, une colonne par point de contrôle de l&apos;état source ; les nombres comme 1/3 sont lus exactement</translation>
    </message>
    <message>
        <source>Apply Matrix</source>
        <translation>Appliquer la matrice</translation>
    </message>
    <message>
        <source>Apply Affine Map</source>
        <translation>Appliquer l&apos;application affine</translation>
    </message>
    <message>
        <source>x ↦ x A + b, taking the target state&apos;s frame triangle into the plane of the source&apos;s; kept as its matrix</source>
        <translation>x ↦ x A + b, envoyant le triangle de repère de l&apos;état cible dans le plan de celui de l&apos;état source ; conservée sous forme de sa matrice</translation>
    </message>
    <message>
        <source>Bézier (de Casteljau at 1/2)</source>
        <translation>Bézier (de Casteljau en 1/2)</translation>
    </message>
    <message>
        <source>Uniform B-spline</source>
        <translation>B-spline uniforme</translation>
    </message>
    <message>
        <source>End-interpolating B-spline</source>
        <translation>B-spline interpolant les extrémités</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Four-point</source>
        <translation>Quatre points</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Degré</translation>
    </message>
    <message>
        <source>Piece S_i, i =</source>
        <translation>Morceau S_i, i =</translation>
    </message>
    <message>
        <source>Apply Scheme Piece</source>
        <translation>Appliquer le morceau de schéma</translation>
    </message>
    <message>
        <source>The analysis of a controlled IFS item: its constrained joint spectral radius, its cycles&apos; spectra and the Lyapunov exponent of random iteration.</source>
        <translation>L&apos;analyse d&apos;un élément IFS contrôlé : son rayon spectral joint contraint, les spectres de ses cycles et l&apos;exposant de Lyapunov de l&apos;itération aléatoire.</translation>
    </message>
    <message>
        <source>All states</source>
        <translation>Tous les états</translation>
    </message>
    <message>
        <source>Analysing the automaton…</source>
        <translation>Analyse de l&apos;automate…</translation>
    </message>
    <message>
        <source>Automaton of %1</source>
        <translation>Automate de %1</translation>
    </message>
    <message>
        <source>%1 control points (its barycentric space), %2 arcs leave it, %3 arrive. Drag its control points in the attractor view.</source>
        <translation>%1 points de contrôle (son espace barycentrique), %2 arcs en partent, %3 y arrivent. Faites glisser ses points de contrôle dans la vue de l&apos;attracteur.</translation>
    </message>
    <message>
        <source>S is %1 × %2: a row per point of %3, a column per point of %4. It maps the space of %3 into that of %4.</source>
        <translation>S est de taille %1 × %2 : une ligne par point de %3, une colonne par point de %4. Elle envoie l&apos;espace de %3 dans celui de %4.</translation>
    </message>
    <message>
        <source>no controlled IFS item is selected</source>
        <translation>aucun élément IFS contrôlé n&apos;est sélectionné</translation>
    </message>
    <message>
        <source>row %1, column %2 of the matrix is not a number: %3</source>
        <translation>la ligne %1, colonne %2 de la matrice n&apos;est pas un nombre : %3</translation>
    </message>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 n&apos;est pas un nombre</translation>
    </message>
    <message>
        <source>Select a controlled IFS item to see and edit its automaton (Item &gt; Add &gt; Controlled IFS, or the example 003 Fig. 5).</source>
        <translation>Sélectionnez un élément IFS contrôlé pour voir et modifier son automate (Élément &gt; Ajouter &gt; IFS contrôlé, ou l&apos;exemple 003 Fig. 5).</translation>
    </message>
</context>
<context>
    <name>awb::BcifsJunctionItem</name>
    <message>
        <source>Junction</source>
        <translation>Jonction</translation>
    </message>
    <message>
        <source>Change junction of %1</source>
        <translation>Modifier la jonction de %1</translation>
    </message>
    <message>
        <source>e = %1, p = %2 (column sums). %3</source>
        <translation>e = %1, p = %2 (sommes des colonnes). %3</translation>
    </message>
    <message>
        <source>a junction is drawn by an automaton, not by one lifted IFS</source>
        <translation>une jonction est tracée par un automate, pas par un seul IFS relevé</translation>
    </message>
    <message>
        <source>Cubic–quadratic (003 §4.1)</source>
        <translation>Cubique–quadratique (003 §4.1)</translation>
    </message>
    <message>
        <source>Refined, with handles (003 §5)</source>
        <translation>Raffinée, avec poignées (003 §5)</translation>
    </message>
    <message>
        <source>Last column (a, b, c, d, e) of T^l; e = 1 − a − b − c − d (003 §4.1)</source>
        <translation>Dernière colonne (a, b, c, d, e) de T^l&#x202f;; e = 1 − a − b − c − d (003 §4.1)</translation>
    </message>
    <message>
        <source>First column (k, l, m, n, p) of T^r; p = 1 − k − l − m − n (003 §4.1)</source>
        <translation>Première colonne (k, l, m, n, p) de T^r&#x202f;; p = 1 − k − l − m − n (003 §4.1)</translation>
    </message>
    <message>
        <source>Left eigenvalue j</source>
        <translation>Valeur propre j (côté gauche)</translation>
    </message>
    <message>
        <source>Tangent eigenvalue of T^il (003 §5)</source>
        <translation>Valeur propre tangente de T^il (003 §5)</translation>
    </message>
    <message>
        <source>Right eigenvalue r</source>
        <translation>Valeur propre r (côté droit)</translation>
    </message>
    <message>
        <source>Tangent eigenvalue of T^ir (003 §5)</source>
        <translation>Valeur propre tangente de T^ir (003 §5)</translation>
    </message>
    <message>
        <source>BCIFS junction curve</source>
        <translation>Courbe de jonction BCIFS</translation>
    </message>
    <message>
        <source>Left cubic</source>
        <translation>Cubique gauche</translation>
    </message>
    <message>
        <source>Right quadratic</source>
        <translation>Quadratique droite</translation>
    </message>
    <message>
        <source>Handles</source>
        <translation>Poignées</translation>
    </message>
</context>
<context>
    <name>awb::BezierUnionItem</name>
    <message>
        <source>Bézier union</source>
        <translation>Union de Bézier</translation>
    </message>
    <message>
        <source>%1 split parameters for %2 curves</source>
        <translation type="vanished">%1 paramètres de découpe pour %2 courbes</translation>
    </message>
    <message>
        <source>Change Bézier union %1</source>
        <translation>Modifier l’union de Bézier %1</translation>
    </message>
    <message>
        <source>curve %1: %2</source>
        <translation>courbe %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>curves drawn in the lifted space of 000 §2: %1</source>
        <translation>courbes tracées dans l’espace relevé de 000 §2&#xa0;: %1</translation>
    </message>
    <message>
        <source>every composition of %1 maps contracts (factor %2): the dusty fractal of 002 §6 is the unique attractor</source>
        <translation>toute composée de %1 applications est contractante (facteur %2)&#xa0;: la fractale poussiéreuse de 002 §6 est l’unique attracteur</translation>
    </message>
    <message>
        <source>no contraction was proven (best bound %1 at length %2): the picture may not be an attractor</source>
        <translation>aucune contraction n’a pu être démontrée (meilleure borne %1 pour la longueur %2)&#xa0;: l’image n’est peut-être pas un attracteur</translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="vanished">manquant</translation>
    </message>
    <message>
        <source>expected a non-empty array of curves {&quot;control_points&quot;: [...], &quot;u&quot;: number}</source>
        <translation>tableau non vide de courbes {&quot;control_points&quot;: [...], &quot;u&quot;: nombre} attendu</translation>
    </message>
    <message>
        <source>expected an object with &quot;control_points&quot; and &quot;u&quot;</source>
        <translation>objet avec &quot;control_points&quot; et &quot;u&quot; attendu</translation>
    </message>
    <message>
        <source>Union</source>
        <translation>Union</translation>
    </message>
    <message>
        <source>Exact union (block IFS, 000 §2.2)</source>
        <translation>Union exacte (IFS par blocs, 000 §2.2)</translation>
    </message>
    <message>
        <source>All maps together (dusty fractal, 002 §6)</source>
        <translation>Toutes les applications ensemble (fractale poussiéreuse, 002 §6)</translation>
    </message>
    <message>
        <source>Split parameter u</source>
        <translation>Paramètre de découpe u</translation>
    </message>
    <message>
        <source>Curve %1</source>
        <translation>Courbe %1</translation>
    </message>
    <message>
        <source>de Casteljau split at u, 0 &lt; u &lt; 1 (002 eqs. (9)-(10)); the curve is the same for every u, the IFS is not</source>
        <translation>découpe de de Casteljau en u, 0 &lt; u &lt; 1 (002 éq. (9)-(10))&#x202f;; la courbe est la même pour tout u, l’IFS ne l’est pas</translation>
    </message>
    <message>
        <source>Union of Bézier curves</source>
        <translation>Union de courbes de Bézier</translation>
    </message>
    <message>
        <source>Curves</source>
        <translation>Courbes</translation>
    </message>
    <message>
        <source>Each curve&apos;s control points and split parameter u</source>
        <translation>Les points de contrôle et le paramètre de découpe u de chaque courbe</translation>
    </message>
</context>
<context>
    <name>awb::BezierUnionSpec</name>
    <message>
        <source>a union needs at least one curve</source>
        <translation>une union demande au moins une courbe</translation>
    </message>
    <message>
        <source>the split parameter u = %1 must satisfy 0 &lt; u &lt; 1 (002 §3)</source>
        <translation>le paramètre de découpe u = %1 doit vérifier 0 &lt; u &lt; 1 (002 §3)</translation>
    </message>
    <message>
        <source>%1 split parameters for %2 curves</source>
        <translation>%1 paramètres de découpe pour %2 courbes</translation>
    </message>
</context>
<context>
    <name>awb::CharacteristicMapView</name>
    <message>
        <source>The characteristic map: the n faces around the vertex under the two eigenvectors of the subdominant eigenvalue. Cells where the Jacobian changes sign are red.</source>
        <translation>L’application caractéristique&#xa0;: les n faces autour du sommet, transformées par les deux vecteurs propres de la valeur propre sous-dominante. Les cellules où le jacobien change de signe sont en rouge.</translation>
    </message>
    <message>
        <source>Click an extraordinary vertex in the 3D view to see its characteristic map.</source>
        <translation>Cliquez sur un sommet extraordinaire dans la vue 3D pour voir son application caractéristique.</translation>
    </message>
    <message>
        <source>n = %1: regular, %2</source>
        <translation>n = %1&#xa0;: régulière, %2</translation>
    </message>
    <message>
        <source>injective</source>
        <translation>injective</translation>
    </message>
    <message>
        <source>not injective</source>
        <translation>non injective</translation>
    </message>
    <message>
        <source>n = %1: the Jacobian changes sign in %2 cells</source>
        <translation>n = %1&#xa0;: le jacobien change de signe dans %2 cellules</translation>
    </message>
</context>
<context>
    <name>awb::CheckedSpinBox</name>
    <message>
        <source>“%1” is not a whole number.</source>
        <translation>« %1 » n’est pas un nombre entier.</translation>
    </message>
    <message>
        <source>%1 is outside %2 … %3.</source>
        <translation>%1 est hors de %2 … %3.</translation>
    </message>
</context>
<context>
    <name>awb::CifsItem</name>
    <message>
        <source>Fern of gaskets</source>
        <translation>Fougère de triangles de Sierpiński</translation>
    </message>
    <message>
        <source>Change automaton of %1</source>
        <translation>Modifier l’automate de %1</translation>
    </message>
    <message>
        <source>the frame needs exactly 3 points, got %1</source>
        <translation type="vanished">le repère demande exactement 3 points (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>a controlled IFS has no single lifted IFS</source>
        <translation>un IFS contrôlé n’a pas d’IFS relevé unique</translation>
    </message>
    <message>
        <source>Arc T%1 of the fern leads into the Sierpiński state (003 §2.2, Fig. 4).</source>
        <translation type="vanished">L’arc T%1 de la fougère mène à l’état de Sierpiński (003 §2.2, fig. 4).</translation>
    </message>
    <message>
        <source>Automaton</source>
        <translation>Automate</translation>
    </message>
    <message>
        <source>Redirected arc</source>
        <translation type="vanished">Arc redirigé</translation>
    </message>
    <message>
        <source>The fern map (0 stem, 1 main frond, 2 left, 3 right leaflet) whose arc leads into the Sierpiński state (003 Fig. 4)</source>
        <translation type="vanished">L’application de la fougère (0 tige, 1 fronde principale, 2 foliole gauche, 3 foliole droite) dont l’arc mène à l’état de Sierpiński (003 fig. 4)</translation>
    </message>
    <message>
        <source>Drawn state</source>
        <translation>État tracé</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn</source>
        <translation type="vanished">L’état dont l’attracteur est tracé</translation>
    </message>
    <message>
        <source>Controlled IFS</source>
        <translation>IFS contrôlé</translation>
    </message>
    <message>
        <source>Fern of gaskets (003 Fig. 4)</source>
        <translation type="vanished">Fougère de triangles de Sierpiński (003 Fig. 4)</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation type="vanished">Repère</translation>
    </message>
    <message>
        <source>a controlled IFS draws its arcs by their own weights (&quot;arcs&quot;): leave the algorithm&apos;s probabilities empty</source>
        <translation>un IFS contrôlé tire ses arcs selon leurs propres poids (&quot;arcs&quot;) : laissez vides les probabilités de l&apos;algorithme</translation>
    </message>
    <message>
        <source>arcs between states of different dimensions have rectangular matrices: see the automaton&apos;s analysis</source>
        <translation>les arcs entre des états de dimensions différentes ont des matrices rectangulaires : voir l&apos;analyse de l&apos;automate</translation>
    </message>
    <message>
        <source>The union of the attractors of the automaton&apos;s %1 states (003 §2.2).</source>
        <translation>L&apos;union des attracteurs des %1 états de l&apos;automate (003 §2.2).</translation>
    </message>
    <message>
        <source>The attractor of state %1 of the automaton (003 §2.2).</source>
        <translation>L&apos;attracteur de l&apos;état %1 de l&apos;automate (003 §2.2).</translation>
    </message>
    <message>
        <source>States</source>
        <translation>États</translation>
    </message>
    <message>
        <source>Each state&apos;s name and control points (its barycentric space)</source>
        <translation>Le nom et les points de contrôle de chaque état (son espace barycentrique)</translation>
    </message>
    <message>
        <source>Arcs</source>
        <translation>Arcs</translation>
    </message>
    <message>
        <source>Each arc&apos;s states and matrix S (a row per point of the state it leads to, rows summing to 1) and weight</source>
        <translation>Les états, la matrice S (une ligne par point de l&apos;état vers lequel il mène, lignes de somme 1) et le poids de chaque arc</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn, or the union of all</source>
        <translation>L&apos;état dont l&apos;attracteur est tracé, ou l&apos;union de tous</translation>
    </message>
</context>
<context>
    <name>awb::CifsSpec</name>
    <message>
        <source>the redirected fern arc must be 0 … 3 (T0 … T3), got %1</source>
        <translation type="vanished">l’arc redirigé de la fougère doit être 0 … 3 (T0 … T3) (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>no state &quot;%1&quot;; the states are &quot;%2&quot;</source>
        <translation type="vanished">aucun état &quot;%1&quot;&#x202f;; les états sont &quot;%2&quot;</translation>
    </message>
    <message>
        <source>expected a matrix: a non-empty array of rows</source>
        <translation>matrice attendue : un tableau non vide de lignes</translation>
    </message>
    <message>
        <source>a %1 x %2 matrix: a state has at most %3 points</source>
        <translation>une matrice %1 x %2 : un état a au plus %3 points</translation>
    </message>
    <message>
        <source>expected a row of %1 numbers, like row 1</source>
        <translation>ligne de %1 nombres attendue, comme la ligne 1</translation>
    </message>
    <message>
        <source>no state %1; the states are %2</source>
        <translation>aucun état %1 ; les états sont %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>expected a state&apos;s name</source>
        <translation>nom d&apos;état attendu</translation>
    </message>
    <message>
        <source>missing: give the arc&apos;s map as &quot;matrix&quot;, &quot;columns&quot;, &quot;affine&quot; or &quot;scheme&quot;</source>
        <translation>manquant : donnez l&apos;application de l&apos;arc sous la forme &quot;matrix&quot;, &quot;columns&quot;, &quot;affine&quot; ou &quot;scheme&quot;</translation>
    </message>
    <message>
        <source>give the arc&apos;s map one way, not as %1</source>
        <translation>donnez l&apos;application de l&apos;arc d&apos;une seule façon, pas comme %1</translation>
    </message>
    <message>
        <source> and </source>
        <translation> et </translation>
    </message>
    <message>
        <source>a plane affine map needs both states to have 3 control points (a frame triangle): %1 has %2, %3 has %4</source>
        <translation>une application affine du plan exige que les deux états aient 3 points de contrôle (un triangle de repère) : %1 en a %2, %3 en a %4</translation>
    </message>
    <message>
        <source>expected {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</source>
        <translation>attendu : {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</translation>
    </message>
    <message>
        <source>A must be 2 x 2 and b two numbers</source>
        <translation>A doit être 2 x 2 et b deux nombres</translation>
    </message>
    <message>
        <source>expected a curve scheme, as a curve item&apos;s &quot;scheme&quot;</source>
        <translation>schéma de courbe attendu, comme le &quot;scheme&quot; d&apos;un élément courbe</translation>
    </message>
    <message>
        <source>a scheme&apos;s matrix is square: %1 has %2 points, %3 has %4</source>
        <translation>la matrice d&apos;un schéma est carrée : %1 a %2 points, %3 en a %4</translation>
    </message>
    <message>
        <source>an automaton needs at least one state</source>
        <translation>un automate nécessite au moins un état</translation>
    </message>
    <message>
        <source>%1 states: at most %2</source>
        <translation>%1 états : au plus %2</translation>
    </message>
    <message>
        <source>a state needs a name</source>
        <translation>un état doit avoir un nom</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names all states; call the state otherwise</source>
        <translation>&quot;%1&quot; désigne tous les états ; nommez l&apos;état autrement</translation>
    </message>
    <message>
        <source>two states are called %1</source>
        <translation>deux états s&apos;appellent %1</translation>
    </message>
    <message>
        <source>a state needs 1 to %1 control points, got %2</source>
        <translation>un état nécessite de 1 à %1 points de contrôle, reçu %2</translation>
    </message>
    <message>
        <source>state %1 has a control point that is not finite</source>
        <translation>l&apos;état %1 a un point de contrôle qui n&apos;est pas fini</translation>
    </message>
    <message>
        <source>%1 arcs: at most %2 (addresses are bytes)</source>
        <translation>%1 arcs : au plus %2 (les adresses sont des octets)</translation>
    </message>
    <message>
        <source>an arc needs a name</source>
        <translation>un arc doit avoir un nom</translation>
    </message>
    <message>
        <source>two arcs are called %1</source>
        <translation>deux arcs s&apos;appellent %1</translation>
    </message>
    <message>
        <source>arc %1 leads between states that do not exist</source>
        <translation>l&apos;arc %1 relie des états qui n&apos;existent pas</translation>
    </message>
    <message>
        <source>arc %1 has a %2 x %3 matrix; from %4 (%5 points) to %6 (%7 points) it must be %7 x %5: a row per point of %6</source>
        <translation>l&apos;arc %1 a une matrice %2 x %3 ; de %4 (%5 points) à %6 (%7 points), elle doit être %7 x %5 : une ligne par point de %6</translation>
    </message>
    <message>
        <source>arc %1 has a matrix entry that is not finite</source>
        <translation>l&apos;arc %1 a un coefficient de matrice qui n&apos;est pas fini</translation>
    </message>
    <message>
        <source>row %1 of arc %2 sums to %3, not 1: the map would not keep barycentric coordinates</source>
        <translation>la ligne %1 de l&apos;arc %2 a pour somme %3, et non 1 : l&apos;application ne conserverait pas les coordonnées barycentriques</translation>
    </message>
    <message>
        <source>the weight of arc %1 must be a number &gt; 0</source>
        <translation>le poids de l&apos;arc %1 doit être un nombre &gt; 0</translation>
    </message>
    <message>
        <source>no state %1 to draw; the states are %2</source>
        <translation>aucun état %1 à tracer ; les états sont %2</translation>
    </message>
    <message>
        <source>expected a non-empty array of states {&quot;name&quot;: text, &quot;control_points&quot;: [...]}</source>
        <translation>tableau non vide d&apos;états attendu {&quot;name&quot;: texte, &quot;control_points&quot;: [...]}</translation>
    </message>
    <message>
        <source>expected an object with &quot;name&quot; and &quot;control_points&quot;</source>
        <translation>objet attendu avec &quot;name&quot; et &quot;control_points&quot;</translation>
    </message>
    <message>
        <source>unknown field of a state</source>
        <translation>champ inconnu d&apos;un état</translation>
    </message>
    <message>
        <source>expected an array of arcs {&quot;name&quot;, &quot;from&quot;, &quot;to&quot;, &quot;matrix&quot;}</source>
        <translation>tableau d&apos;arcs attendu {&quot;name&quot;, &quot;from&quot;, &quot;to&quot;, &quot;matrix&quot;}</translation>
    </message>
    <message>
        <source>expected an object with &quot;from&quot;, &quot;to&quot; and the arc&apos;s map</source>
        <translation>objet attendu avec &quot;from&quot;, &quot;to&quot; et l&apos;application de l&apos;arc</translation>
    </message>
    <message>
        <source>unknown field of an arc</source>
        <translation>champ inconnu d&apos;un arc</translation>
    </message>
    <message>
        <source>All states</source>
        <translation>Tous les états</translation>
    </message>
</context>
<context>
    <name>awb::ComplexBezierItem</name>
    <message>
        <source>Complex Bézier</source>
        <translation>Bézier complexe</translation>
    </message>
    <message>
        <source>the parameter t must be a finite complex number</source>
        <translation>le paramètre t doit être un nombre complexe fini</translation>
    </message>
    <message>
        <source>Change t of %1</source>
        <translation>Modifier t de %1</translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="vanished">manquant</translation>
    </message>
    <message>
        <source>expected [re, im]</source>
        <translation>[re, im] attendu</translation>
    </message>
    <message>
        <source>Split parameter t</source>
        <translation>Paramètre de découpe t</translation>
    </message>
    <message>
        <source>Curve</source>
        <translation>Courbe</translation>
    </message>
    <message>
        <source>de Casteljau split at a complex t; inside both discs |t| &lt; 1 and |1 − t| &lt; 1 the curve is a fractal (004 §3.7, Fig. 3.3)</source>
        <translation>découpe de de Casteljau en un t complexe&#x202f;; à l’intérieur des deux disques |t| &lt; 1 et |1 − t| &lt; 1, la courbe est une fractale (004 §3.7, fig. 3.3)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid value for %2</source>
        <translation type="vanished">«&#xa0;%1&#xa0;» n’est pas une valeur valide pour %2</translation>
    </message>
    <message>
        <source>Complex Bézier curve</source>
        <translation>Courbe de Bézier complexe</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Points de contrôle</translation>
    </message>
    <message>
        <source>Scaled coordinates g(z, 1/(2y)) = Re z + i Im z / (2y), y = %1 (004 eq. (3.40)): as y → 0 the curve approaches the Takagi graph x + i T(x) (Thm 3.7.3, Figs. 3.6–3.8). %2</source>
        <translation>Coordonnées mises à l&apos;échelle g(z, 1/(2y)) = Re z + i Im z / (2y), y = %1 (004 eq. (3.40)) : quand y → 0, la courbe tend vers le graphe de Takagi x + i T(x) (Thm 3.7.3, Figs. 3.6–3.8). %2</translation>
    </message>
    <message>
        <source>Scaled coordinates apply to t = 1/2 + iy with y ≠ 0 and control points on the real axis (004 Thm 3.7.3); drawn unscaled. %1</source>
        <translation>Les coordonnées mises à l&apos;échelle s&apos;appliquent à t = 1/2 + iy avec y ≠ 0 et des points de contrôle sur l&apos;axe réel (004 Thm 3.7.3) ; tracé sans mise à l&apos;échelle. %1</translation>
    </message>
    <message>
        <source>Change scaled coordinates of %1</source>
        <translation>Modifier les coordonnées mises à l&apos;échelle de %1</translation>
    </message>
    <message>
        <source>Scaled coordinates g(z, 1/(2y))</source>
        <translation>Coordonnées mises à l&apos;échelle g(z, 1/(2y))</translation>
    </message>
    <message>
        <source>Draw Re z + i Im z / (2y) for t = 1/2 + iy: the coordinates of 004 Thm 3.7.3 and Figs. 3.6–3.8, where the curve approaches the Takagi graph</source>
        <translation>Tracer Re z + i Im z / (2y) pour t = 1/2 + iy : les coordonnées de 004 Thm 3.7.3 et des Figs. 3.6–3.8, où la courbe tend vers le graphe de Takagi</translation>
    </message>
</context>
<context>
    <name>awb::ComplexPlanePicker</name>
    <message>
        <source>Drag t in the complex plane. The attractor exists inside the lens where |t| &lt; 1 and |1 − t| &lt; 1 (both maps contract, 004 Fig. 3.3).</source>
        <translation>Faites glisser t dans le plan complexe. L’attracteur existe à l’intérieur de la lentille où |t| &lt; 1 et |1 − t| &lt; 1 (les deux applications sont contractantes, 004 fig. 3.3).</translation>
    </message>
</context>
<context>
    <name>awb::ControlPointEdits</name>
    <message>
        <source>There is no such point set.</source>
        <translation>Cet ensemble de points n’existe pas.</translation>
    </message>
    <message>
        <source>%1 (%2) has a fixed number of control points.</source>
        <translation>%1 (%2) a un nombre fixe de points de contrôle.</translation>
    </message>
    <message>
        <source>A Bézier curve of degree %1 is refused: %2</source>
        <translation>Une courbe de Bézier de degré %1 est refusée&#xa0;: %2</translation>
    </message>
    <message>
        <source>There is no point %1.</source>
        <translation>Le point %1 n’existe pas.</translation>
    </message>
    <message>
        <source>Insert control point %1 into %2</source>
        <translation>Insérer le point de contrôle %1 dans %2</translation>
    </message>
    <message>
        <source>No control point is selected.</source>
        <translation>Aucun point de contrôle n’est sélectionné.</translation>
    </message>
    <message>
        <source>%1 needs at least %2 control points.</source>
        <translation>%1 demande au moins %2 points de contrôle.</translation>
    </message>
    <message>
        <source>Delete control point %1 of %2</source>
        <translation>Supprimer le point de contrôle %1 de %2</translation>
    </message>
    <message>
        <source>Delete %1 control points of %2</source>
        <translation>Supprimer %1 points de contrôle de %2</translation>
    </message>
</context>
<context>
    <name>awb::DensityFile</name>
    <message>
        <source>cannot write %1: the picture is empty</source>
        <translation>impossible d’écrire %1&#xa0;: l’image est vide</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>impossible de lire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>cannot write %1: not enough memory</source>
        <translation>impossible d’écrire %1&#xa0;: mémoire insuffisante</translation>
    </message>
    <message>
        <source>%1; alpha = log(1 + hits) / log(1 + %2); world %3 %4 %5 %6</source>
        <translation>%1&#xa0;; alpha = log(1 + impacts) / log(1 + %2)&#xa0;; monde %3 %4 %5 %6</translation>
    </message>
</context>
<context>
    <name>awb::EigenvaluePlotItem</name>
    <message>
        <source>Eigenvalues</source>
        <translation>Valeurs propres</translation>
    </message>
    <message>
        <source>S_i, the subdivision matrices</source>
        <translation>S_i, les matrices de subdivision</translation>
    </message>
    <message>
        <source>A_i, the linear parts of M_i</source>
        <translation>A_i, les parties linéaires des M_i</translation>
    </message>
    <message>
        <source>M_i = P⁻¹S_iP, the lifted maps</source>
        <translation>M_i = P⁻¹S_iP, les applications relevées</translation>
    </message>
    <message>
        <source>Change the source of %1</source>
        <translation>Modifier la source de %1</translation>
    </message>
    <message>
        <source>Analyse the matrices %1 in %2</source>
        <translation>Analyser les matrices %1 de %2</translation>
    </message>
    <message>
        <source>M_i is defined only for a lifted subdivision IFS</source>
        <translation>M_i n’est défini que pour un IFS de subdivision relevé</translation>
    </message>
    <message>
        <source>no item is chosen to analyse</source>
        <translation>aucun élément n’est choisi pour l’analyse</translation>
    </message>
    <message>
        <source>there is no item called &quot;%1&quot;</source>
        <translation>aucun élément ne s’appelle «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>&quot;%1&quot; (%2) has no matrices to analyse</source>
        <translation>«&#xa0;%1&#xa0;» (%2) n’a pas de matrices à analyser</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be computed: %2</source>
        <translation>«&#xa0;%1&#xa0;» ne peut pas être calculé&#xa0;: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no matrices %2: %3</source>
        <translation>«&#xa0;%1&#xa0;» n’a pas de matrices %2&#xa0;: %3</translation>
    </message>
    <message>
        <source>Eigenvalue plot</source>
        <translation>Diagramme des valeurs propres</translation>
    </message>
    <message>
        <source>Analyse the centre of face %1 in %2</source>
        <translation>Analyser le centre de la face %1 de %2</translation>
    </message>
    <message>
        <source>Analyse vertex %1 in %2</source>
        <translation>Analyser le sommet %1 de %2</translation>
    </message>
    <message>
        <source>Analyse the mesh&apos;s matrices in %1</source>
        <translation>Analyser les matrices du maillage de %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a mesh: it has no extraordinary vertices</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas un maillage&#xa0;: il n’a pas de sommets extraordinaires</translation>
    </message>
    <message>
        <source>the centre of face %1 of &quot;%2&quot; is not an extraordinary vertex</source>
        <translation>le centre de la face %1 de «&#xa0;%2&#xa0;» n’est pas un sommet extraordinaire</translation>
    </message>
    <message>
        <source>vertex %1 of &quot;%2&quot; is not an extraordinary vertex</source>
        <translation>le sommet %1 de «&#xa0;%2&#xa0;» n’est pas un sommet extraordinaire</translation>
    </message>
    <message>
        <source>an extraordinary vertex has its local subdivision matrix S only</source>
        <translation>un sommet extraordinaire n’a que sa matrice de subdivision locale S</translation>
    </message>
    <message>
        <source>expected a vertex or face number (0-based)</source>
        <translation>numéro de sommet ou de face attendu (numéroté à partir de 0)</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(aucun)</translation>
    </message>
    <message>
        <source>%1 (missing)</source>
        <translation>%1 (manquant)</translation>
    </message>
    <message>
        <source>(the mesh&apos;s matrices)</source>
        <translation>(les matrices du maillage)</translation>
    </message>
    <message>
        <source>vertex %1 (n = %2)</source>
        <translation>sommet %1 (n = %2)</translation>
    </message>
    <message>
        <source>centre of face %1 (n = %2)</source>
        <translation>centre de la face %1 (n = %2)</translation>
    </message>
    <message>
        <source>centre of face %1 (missing)</source>
        <translation>centre de la face %1 (manquant)</translation>
    </message>
    <message>
        <source>vertex %1 (missing)</source>
        <translation>sommet %1 (manquant)</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <source>The item whose matrices are analysed</source>
        <translation>L’élément dont les matrices sont analysées</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>Matrices</translation>
    </message>
    <message>
        <source>S_i: the subdivision matrices (their eigenvalue 1 is affine invariance); A_i: the linear parts of the lifted maps, whose subdominant eigenvalue decides the tangents; M_i: the lifted maps themselves (003 §4, 004 §2.1)</source>
        <translation>S_i&#xa0;: les matrices de subdivision (leur valeur propre 1 traduit l’invariance affine)&#x202f;; A_i&#xa0;: les parties linéaires des applications relevées, dont la valeur propre sous-dominante détermine les tangentes&#x202f;; M_i&#xa0;: les applications relevées elles-mêmes (003 §4, 004 §2.1)</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Sommet</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Face</translation>
    </message>
    <message>
        <source>For a mesh surface: the extraordinary vertex whose local subdivision matrix is analysed</source>
        <translation>Pour une surface de maillage&#xa0;: le sommet extraordinaire dont la matrice de subdivision locale est analysée</translation>
    </message>
</context>
<context>
    <name>awb::ExactCurve</name>
    <message>
        <source>Bézier curve c([0, 1])</source>
        <translation>courbe de Bézier c([0, 1])</translation>
    </message>
    <message>
        <source>Takagi image c(x + 2iy·T(x)), y = %1 (Conj. 3.7.1)</source>
        <translation>image de Takagi c(x + 2iy·T(x)), y = %1 (conj. 3.7.1)</translation>
    </message>
    <message>
        <source>exact curve: %1</source>
        <translation>courbe exacte&#xa0;: %1</translation>
    </message>
    <message>
        <source>Takagi graph x + i T(x), scaled (004 Thm 3.7.3)</source>
        <translation>Graphe de Takagi x + i T(x), mis à l&apos;échelle (004 Thm 3.7.3)</translation>
    </message>
</context>
<context>
    <name>awb::ExactSpinBox</name>
    <message>
        <source>“%1” is not a number (type e.g. 0.25, 1/3 or sqrt(3)/6).</source>
        <translation>« %1 » n’est pas un nombre (tapez par exemple 0.25, 1/3 ou sqrt(3)/6).</translation>
    </message>
    <message>
        <source>%1 is outside %2 … %3.</source>
        <translation>%1 est hors de %2 … %3.</translation>
    </message>
</context>
<context>
    <name>awb::ExampleGallery</name>
    <message>
        <source>Open Example</source>
        <translation>Ouvrir un exemple</translation>
    </message>
    <message>
        <source>One project per figure of the papers, and examples of meshes, masks and animations. An example opens as a copy: Save As keeps it.</source>
        <translation>Un projet par figure des articles, ainsi que des exemples de maillages, de masques et d’animations. Un exemple s’ouvre sous forme de copie&#xa0;: «&#xa0;Enregistrer sous&#xa0;» la conserve.</translation>
    </message>
    <message>
        <source>Filter: a paper (003), a figure, a word (Koch, mesh)…</source>
        <translation>Filtrer&#xa0;: un article (003), une figure, un mot (Koch, mesh)…</translation>
    </message>
    <message>
        <source>No examples installed</source>
        <translation>Aucun exemple installé</translation>
    </message>
</context>
<context>
    <name>awb::ExportDialog</name>
    <message>
        <source>Export Figure</source>
        <translation>Exporter la figure</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;LaTeX matrices (*.tex)</source>
        <translation type="vanished">Image PNG (*.png);;Dessin SVG (*.svg);;Document PDF (*.pdf);;Matrices LaTeX (*.tex)</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;LaTeX matrices (*.tex);;OpenEXR raw density of the attractor, float32 hits per pixel (*.exr)</source>
        <translation>Image PNG (*.png);;Dessin SVG (*.svg);;Document PDF (*.pdf);;Matrices LaTeX (*.tex);;Densité brute OpenEXR de l’attracteur, impacts par pixel en float32 (*.exr)</translation>
    </message>
</context>
<context>
    <name>awb::FieldReader</name>
    <message>
        <source>missing</source>
        <translation>manquant</translation>
    </message>
    <message>
        <source>expected a string</source>
        <translation>chaîne attendue</translation>
    </message>
    <message>
        <source>expected one of %1, got %2</source>
        <translation>une valeur parmi %1 attendue (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>expected an integer</source>
        <translation>entier attendu</translation>
    </message>
    <message>
        <source>expected an integer between %1 and %2</source>
        <translation>entier attendu entre %1 et %2</translation>
    </message>
    <message>
        <source>expected an array of numbers</source>
        <translation>tableau de nombres attendu</translation>
    </message>
    <message>
        <source>expected an array of points [x, y, z]</source>
        <translation>tableau de points [x, y, z] attendu</translation>
    </message>
    <message>
        <source>expected an array of points [x, y]</source>
        <translation>tableau de points [x, y] attendu</translation>
    </message>
    <message>
        <source>expected an array of matrices</source>
        <translation>tableau de matrices attendu</translation>
    </message>
    <message>
        <source>expected a matrix: a non-empty array of rows</source>
        <translation>matrice attendue : un tableau non vide de lignes</translation>
    </message>
    <message>
        <source>expected a row: a non-empty array of numbers</source>
        <translation>ligne attendue&#xa0;: un tableau non vide de nombres</translation>
    </message>
    <message>
        <source>row %1 has %2 numbers, row 1 has %3</source>
        <translation>la ligne %1 a %2 nombres, la ligne 1 en a %3</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>objet attendu</translation>
    </message>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1 cannot be read as a double-precision number</source>
        <translation>%1 ne peut pas être lu comme un nombre en double précision</translation>
    </message>
    <message>
        <source>expected a number</source>
        <translation>nombre attendu</translation>
    </message>
    <message>
        <source>expected a finite number</source>
        <translation>nombre fini attendu</translation>
    </message>
    <message>
        <source>expected a point [x, y, z]</source>
        <translation>point [x, y, z] attendu</translation>
    </message>
    <message>
        <source>expected a point [x, y]</source>
        <translation>point [x, y] attendu</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number (a fraction such as &quot;3/8&quot; or an expression such as &quot;(1 + sqrt(3))/8&quot; is)</source>
        <translation>&quot;%1&quot; n&apos;est pas un nombre (une fraction comme &quot;3/8&quot; ou une expression comme &quot;(1 + sqrt(3))/8&quot; en est un)</translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation>true ou false attendu</translation>
    </message>
</context>
<context>
    <name>awb::FigureFile</name>
    <message>
        <source>cannot write %1</source>
        <translation>impossible d&apos;écrire %1</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>impossible d’écrire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>the folder %1 does not exist</source>
        <translation>le dossier %1 n’existe pas</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>c’est un dossier</translation>
    </message>
    <message>
        <source>the file is read-only</source>
        <translation>le fichier est en lecture seule</translation>
    </message>
    <message>
        <source>cannot write %1: it is a folder</source>
        <translation>impossible d’écrire %1&#xa0;: c’est un dossier</translation>
    </message>
    <message>
        <source>%1 has no suffix: name the format (.png, .svg or .pdf)</source>
        <translation>%1 n’a pas d’extension&#xa0;: indiquez le format (.png, .svg ou .pdf)</translation>
    </message>
    <message>
        <source>unknown output format &apos;.%1&apos; (use .png, .svg or .pdf)</source>
        <translation>format de sortie «&#xa0;.%1&#xa0;» inconnu (utilisez .png, .svg ou .pdf)</translation>
    </message>
</context>
<context>
    <name>awb::FigureSheet</name>
    <message>
        <source>yes</source>
        <translation>oui</translation>
    </message>
    <message>
        <source>no</source>
        <translation>non</translation>
    </message>
    <message>
        <source>No item</source>
        <translation>Aucun élément</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>maps = %1</source>
        <translation>applications = %1</translation>
    </message>
    <message>
        <source>control points = %1</source>
        <translation>points de contrôle = %1</translation>
    </message>
    <message>
        <source>depth = %1</source>
        <translation>profondeur = %1</translation>
    </message>
    <message>
        <source>samples = %1</source>
        <translation>échantillons = %1</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more: see the Matrices dock, or copy them as LaTeX.</source>
        <translation>
            <numerusform>… et %n autre&#xa0;: voir le panneau Matrices, ou copier les matrices en LaTeX.</numerusform>
            <numerusform>… et %n autres&#xa0;: voir le panneau Matrices, ou copier les matrices en LaTeX.</numerusform>
        </translation>
    </message>
    <message>
        <source>Printing %1 was cancelled while the attractor was drawn.</source>
        <translation>L’impression de %1 a été annulée pendant le tracé de l’attracteur.</translation>
    </message>
    <message>
        <source>%1 (%2 × %3):</source>
        <translation>%1 (%2 × %3) :</translation>
    </message>
</context>
<context>
    <name>awb::FileWriting</name>
    <message>
        <source>the folder %1 does not exist</source>
        <translation>le dossier %1 n’existe pas</translation>
    </message>
    <message>
        <source>%1 is not a folder</source>
        <translation>%1 n’est pas un dossier</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>c’est un dossier</translation>
    </message>
    <message>
        <source>the file is read-only</source>
        <translation>le fichier est en lecture seule</translation>
    </message>
    <message>
        <source>cannot create a file in the folder %1: %2</source>
        <translation>impossible de créer un fichier dans le dossier %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>the folder %1 is read-only</source>
        <translation>le dossier %1 est en lecture seule</translation>
    </message>
    <message>
        <source>the file is not open</source>
        <translation>le fichier n’est pas ouvert</translation>
    </message>
</context>
<context>
    <name>awb::FlameExchange</name>
    <message>
        <source>the XML is malformed: %1</source>
        <translation type="vanished">le XML est mal formé&#xa0;: %1</translation>
    </message>
    <message>
        <source>%1: the file holds no &lt;flame&gt; element</source>
        <translation type="vanished">%1&#xa0;: le fichier ne contient aucun élément &lt;flame&gt;</translation>
    </message>
    <message>
        <source>%1, line %2, column %3: </source>
        <translation>%1, ligne %2, colonne %3 : </translation>
    </message>
    <message>
        <source>flame %1</source>
        <translation>flamme %1</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;, final xform</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;», xform final</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;, xform %2</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;», xform %2</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: &lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;»&#xa0;: &lt;symmetry&gt; nécessite kind=&quot;k&quot;, un nombre entier</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: element &lt;%2&gt; ignored</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;»&#xa0;: élément &lt;%2&gt; ignoré</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos; has no xform</source>
        <translation type="vanished">la flamme «&#xa0;%1&#xa0;» n’a aucun xform</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be 6 finite numbers</source>
        <translation type="vanished">%1=&quot;%2&quot; doit comporter 6 nombres finis</translation>
    </message>
    <message>
        <source>weight=&quot;%1&quot; must be a finite number &gt;= 0</source>
        <translation type="vanished">weight=&quot;%1&quot; doit être un nombre fini &gt;= 0</translation>
    </message>
    <message>
        <source>var1=&quot;%1&quot; names no variation</source>
        <translation type="vanished">var1=&quot;%1&quot; ne désigne aucune variation</translation>
    </message>
    <message>
        <source>variation %1=&quot;%2&quot; is not a number</source>
        <translation type="vanished">variation %1=&quot;%2&quot; n’est pas un nombre</translation>
    </message>
    <message>
        <source>: opacity %1 not kept (every map is drawn)</source>
        <translation type="vanished">&#xa0;: opacity %1 non conservée (chaque application est dessinée)</translation>
    </message>
    <message>
        <source>: attribute %1=&quot;%2&quot; ignored</source>
        <translation type="vanished">&#xa0;: attribut %1=&quot;%2&quot; ignoré</translation>
    </message>
    <message numerus="yes">
        <source>: variation %1 dropped (non-linear)</source>
        <translation type="vanished">
            <numerusform>&#xa0;: variation %1 abandonnée (non linéaire)</numerusform>
            <numerusform>&#xa0;: variations %1 abandonnées (non linéaires)</numerusform>
        </translation>
    </message>
    <message>
        <source>; its affine part kept as a linear map</source>
        <translation type="vanished">&#xa0;; sa partie affine est conservée comme application linéaire</translation>
    </message>
    <message>
        <source>: no variation given; taken as linear</source>
        <translation type="vanished">&#xa0;: aucune variation indiquée&#xa0;; considérée comme linear</translation>
    </message>
    <message>
        <source>%1: element &lt;%2&gt; ignored (animation)</source>
        <translation type="vanished">%1&#xa0;: élément &lt;%2&gt; ignoré (animation)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: a &lt;color&gt; needs index=&quot;0..255&quot; and rgb=&quot;r g b&quot;</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;»&#xa0;: un élément &lt;color&gt; nécessite index=&quot;0..255&quot; et rgb=&quot;r g b&quot;</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: the palette&apos;s hex digits are not whole colours of %2 digits</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;»&#xa0;: les chiffres hexadécimaux de la palette ne forment pas un nombre entier de couleurs de %2 chiffres</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: palette entry %2 is not hexadecimal</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;»&#xa0;: l’entrée %2 de la palette n’est pas hexadécimale</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: the final xform is not invertible (determinant %2): dropped</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;»&#xa0;: le xform final n’est pas inversible (déterminant %2)&#xa0;: supprimé</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos (chaos) rows forbid some transitions; imported as the plain IFS of its maps, whose attractor contains the flame&apos;s</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;»&#xa0;: ses lignes xaos (chaos) interdisent certaines transitions&#xa0;; importée comme l’IFS simple de ses applications, dont l’attracteur contient celui de la flamme</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos (chaos) weights are dropped: the attractor is the same, its measure differs</source>
        <translation type="vanished">flamme «&#xa0;%1&#xa0;»&#xa0;: ses poids xaos (chaos) sont abandonnés&#xa0;: l’attracteur est le même, sa mesure diffère</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: every xform has weight 0</source>
        <translation>flamme «&#xa0;%1&#xa0;»&#xa0;: tous les xforms ont le poids 0</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2 (%3)</source>
        <translation>flamme «&#xa0;%1&#xa0;»&#xa0;: %2 (%3)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2</source>
        <translation>flamme « %1 » : %2</translation>
    </message>
    <message>
        <source>%1: the file is larger than %2 MB</source>
        <translation type="vanished">%1&#xa0;: le fichier dépasse %2 Mo</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation type="vanished">impossible de lire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>%1 is an IFS of space: a flame holds maps of the plane</source>
        <translation type="vanished">%1 est un IFS de l’espace&#xa0;: une flamme contient des applications du plan</translation>
    </message>
    <message>
        <source>the flame&apos;s frame is empty</source>
        <translation>le cadre de la flamme est vide</translation>
    </message>
    <message>
        <source>: no weight given; taken as 0, as flam3 does (the map is never chosen)</source>
        <translation type="vanished">&#xa0;: aucun poids donné&#xa0;; pris égal à 0, comme le fait flam3 (l’application n’est jamais choisie)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its maps do not contract, not even on average (Lyapunov exponent %2 &gt;= 0), so it has no attractor; flam3 draws it only by discarding the points that escape</source>
        <translation type="vanished">flamme &apos;%1&apos;&#xa0;: ses applications ne sont pas contractantes, pas même en moyenne (exposant de Lyapunov %2 &gt;= 0), elle n&apos;a donc pas d&apos;attracteur&#xa0;; flam3 ne la dessine qu&apos;en écartant les points qui s&apos;échappent</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: more than %2 xforms (at most %2 maps are supported)</source>
        <translation type="vanished">flamme « %1 » : plus de %2 xforms (au plus %2 applications sont prises en charge)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: &lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %2 to %3, got &apos;%4&apos;</source>
        <translation type="vanished">flamme « %1 » : &lt;symmetry&gt; demande kind=&quot;k&quot;, un entier de %2 à %3, reçu « %4 »</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its maps do not contract, not even on average (the Lyapunov exponent of their products, %2, is not clearly negative: not below -0.001), so it may have no attractor; flam3 draws it only by discarding the points that escape</source>
        <translation>flamme « %1 » : ses applications ne sont pas contractantes, même en moyenne (l&apos;exposant de Lyapunov de leurs produits, %2, n&apos;est pas nettement négatif : pas en dessous de -0.001), elle peut donc n&apos;avoir aucun attracteur ; flam3 ne la dessine qu&apos;en écartant les points qui s&apos;échappent</translation>
    </message>
    <message>
        <source>a flam3 flame</source>
        <translation>une flamme flam3</translation>
    </message>
    <message>
        <source>%1 is an IFS of space: a flam3 flame holds maps of the plane (export it as a Fractint .ifs entry)</source>
        <translation>%1 est un IFS de l&apos;espace : une flamme flam3 contient des applications du plan (exportez-le comme entrée Fractint .ifs)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos rows let no xform follow another</source>
        <translation>flamme &apos;%1&apos; : ses lignes xaos ne permettent à aucune xform d&apos;en suivre une autre</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos rows make %2 arcs between its xforms, more than the %3 a controlled IFS may have</source>
        <translation>flamme &apos;%1&apos; : ses lignes xaos créent %2 arcs entre ses xforms, plus que les %3 qu&apos;un IFS contrôlé peut avoir</translation>
    </message>
    <message>
        <source>%1: flame &apos;%2&apos; not imported: %3</source>
        <translation>%1&#xa0;: flamme «&#xa0;%2&#xa0;» non importée&#xa0;: %3</translation>
    </message>
</context>
<context>
    <name>awb::FlameFile</name>
    <message>
        <source>the XML is malformed: %1</source>
        <translation>le XML est mal formé : %1</translation>
    </message>
    <message>
        <source>%1: the file holds no &lt;flame&gt; element</source>
        <translation>%1 : le fichier ne contient aucun élément &lt;flame&gt;</translation>
    </message>
    <message>
        <source>%1, line %2, column %3: </source>
        <translation>%1, ligne %2, colonne %3 : </translation>
    </message>
    <message>
        <source>flame %1</source>
        <translation>flamme %1</translation>
    </message>
    <message>
        <source>a second &lt;finalxform&gt; (flam3 allows one)</source>
        <translation>un second &lt;finalxform&gt; (flam3 n&apos;en autorise qu&apos;un)</translation>
    </message>
    <message>
        <source>more than %1 xforms</source>
        <translation>plus de %1 xforms</translation>
    </message>
    <message>
        <source>final xform</source>
        <translation>xform final</translation>
    </message>
    <message>
        <source>xform %1</source>
        <translation>xform %1</translation>
    </message>
    <message>
        <source>element &lt;%1&gt; ignored</source>
        <translation>élément &lt;%1&gt; ignoré</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2</source>
        <translation>flamme « %1 » : %2</translation>
    </message>
    <message>
        <source>xform %1: its xaos row has %2 entries for %3 xforms; the extra ones are ignored, as flam3 does</source>
        <translation>xform %1 : sa ligne xaos a %2 entrées pour %3 xforms ; celles en trop sont ignorées, comme dans flam3</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; is not a finite number</source>
        <translation>%1=&quot;%2&quot; n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be %3 finite numbers</source>
        <translation>%1=&quot;%2&quot; doit contenir %3 nombres finis</translation>
    </message>
    <message>
        <source>size=&quot;%1&quot; must be two whole numbers from 1 to 32768</source>
        <translation>size=&quot;%1&quot; doit contenir deux entiers de 1 à 32768</translation>
    </message>
    <message>
        <source>scale=&quot;%1&quot; must be positive</source>
        <translation>scale=&quot;%1&quot; doit être positif</translation>
    </message>
    <message>
        <source>zoom=&quot;%1&quot; is beyond +-50 (a factor 2^zoom)</source>
        <translation>zoom=&quot;%1&quot; dépasse +-50 (un facteur 2^zoom)</translation>
    </message>
    <message>
        <source>quality=&quot;%1&quot; must be positive</source>
        <translation>quality=&quot;%1&quot; doit être positif</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be a whole number from 1 to 64</source>
        <translation>%1=&quot;%2&quot; doit être un entier de 1 à 64</translation>
    </message>
    <message>
        <source>attributes not kept: %1</source>
        <translation>attributs non conservés : %1</translation>
    </message>
    <message>
        <source>weight=&quot;%1&quot; is negative</source>
        <translation>weight=&quot;%1&quot; est négatif</translation>
    </message>
    <message>
        <source>color=&quot;%1&quot; must be one or two finite numbers</source>
        <translation>color=&quot;%1&quot; doit contenir un ou deux nombres finis</translation>
    </message>
    <message>
        <source>chaos=&quot;%1&quot; must be at most %2 finite numbers</source>
        <translation>chaos=&quot;%1&quot; doit contenir au plus %2 nombres finis</translation>
    </message>
    <message>
        <source>chaos=&quot;%1&quot; has a negative entry</source>
        <translation>chaos=&quot;%1&quot; contient une valeur négative</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be 6 finite numbers</source>
        <translation>%1=&quot;%2&quot; doit contenir 6 nombres finis</translation>
    </message>
    <message>
        <source>var1=&quot;%1&quot; names no variation</source>
        <translation>var1=&quot;%1&quot; ne désigne aucune variation</translation>
    </message>
    <message>
        <source>var=&quot;...&quot; must be %1 finite numbers, one per variation</source>
        <translation>var=&quot;...&quot; doit contenir %1 nombres finis, un par variation</translation>
    </message>
    <message>
        <source>: a final xform has no weight; weight=&quot;%1&quot; ignored</source>
        <translation>: un xform final n&apos;a pas de poids ; weight=&quot;%1&quot; ignoré</translation>
    </message>
    <message>
        <source>: no weight given; taken as 0, as flam3 does (the xform is never chosen)</source>
        <translation>: aucun poids donné ; pris égal à 0, comme dans flam3 (le xform n&apos;est jamais choisi)</translation>
    </message>
    <message>
        <source>: no variation given: as in flam3, every point goes to post(0)</source>
        <translation>: aucune variation donnée : comme dans flam3, chaque point va en post(0)</translation>
    </message>
    <message>
        <source>: attributes flam3 does not draw, ignored: %1</source>
        <translation>: attributs que flam3 ne dessine pas, ignorés : %1</translation>
    </message>
    <message>
        <source>: animation attributes not kept: %1</source>
        <translation>: attributs d&apos;animation non conservés : %1</translation>
    </message>
    <message>
        <source>: element &lt;%1&gt; ignored (animation)</source>
        <translation>: élément &lt;%1&gt; ignoré (animation)</translation>
    </message>
    <message>
        <source>a &lt;color&gt; needs index=&quot;0..255&quot; and rgb=&quot;r g b&quot;</source>
        <translation>un &lt;color&gt; nécessite index=&quot;0..255&quot; et rgb=&quot;r g b&quot;</translation>
    </message>
    <message>
        <source>a palette of flam3&apos;s palette file (index0) is not kept</source>
        <translation>une palette du fichier de palettes de flam3 (index0) n&apos;est pas conservée</translation>
    </message>
    <message>
        <source>the palette&apos;s hex digits are not at most 256 colours of %1 digits</source>
        <translation>les chiffres hexadécimaux de la palette ne forment pas au plus 256 couleurs de %1 chiffres</translation>
    </message>
    <message>
        <source>palette entry %1 is not hexadecimal</source>
        <translation>l&apos;entrée %1 de la palette n&apos;est pas hexadécimale</translation>
    </message>
    <message>
        <source>&lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %1 to %2</source>
        <translation type="vanished">&lt;symmetry&gt; nécessite kind=&quot;k&quot;, un entier de %1 à %2</translation>
    </message>
    <message>
        <source>&lt;symmetry kind=&quot;%1&quot;&gt; makes more than %2 xforms</source>
        <translation>&lt;symmetry kind=&quot;%1&quot;&gt; produit plus de %2 xforms</translation>
    </message>
    <message>
        <source>&lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %1 to %2, got &apos;%3&apos;</source>
        <translation>&lt;symmetry&gt; nécessite kind=&quot;k&quot;, un entier de %1 à %2, reçu « %3 »</translation>
    </message>
    <message>
        <source>passes=&quot;%1&quot; must be a whole number from 1 to %2</source>
        <translation>passes=&quot;%1&quot; doit être un nombre entier de 1 à %2</translation>
    </message>
    <message>
        <source>%1 is larger than 16 MB</source>
        <translation>%1 dépasse 16 Mo</translation>
    </message>
    <message>
        <source>%1 cannot be read</source>
        <translation>%1 ne peut pas être lu</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>%1 has no palette %2</source>
        <translation>%1 n&apos;a pas de palette %2</translation>
    </message>
    <message>
        <source>its entry %1 has %2 hex digits, not 256 x 8</source>
        <translation>son entrée %1 a %2 chiffres hexadécimaux, pas 256 x 8</translation>
    </message>
    <message>
        <source>its entry %1 is not hexadecimal</source>
        <translation>son entrée %1 n&apos;est pas hexadécimale</translation>
    </message>
    <message>
        <source>palette %1 of flam3&apos;s palette file is not kept: %2</source>
        <translation>la palette %1 du fichier de palettes de flam3 n&apos;est pas conservée : %2</translation>
    </message>
</context>
<context>
    <name>awb::FlameItem</name>
    <message>
        <source>expected 6 numbers in flam3&apos;s order [a, d, b, e, c, f]: x&apos; = a x + b y + c, y&apos; = d x + e y + f</source>
        <translation>6 nombres attendus dans l&apos;ordre de flam3 [a, d, b, e, c, f] : x&apos; = a x + b y + c, y&apos; = d x + e y + f</translation>
    </message>
    <message>
        <source>expected a non-empty array of xforms</source>
        <translation>tableau non vide de xforms attendu</translation>
    </message>
    <message>
        <source>%1 xforms: at most %2 are drawn</source>
        <translation>%1 xforms : au plus %2 sont dessinés</translation>
    </message>
    <message>
        <source>expected 1536 hexadecimal digits (256 colours rrggbb), got %1</source>
        <translation>1536 chiffres hexadécimaux attendus (256 couleurs rrggbb), %1 reçus</translation>
    </message>
    <message>
        <source>colour %1 is not hexadecimal</source>
        <translation>la couleur %1 n&apos;est pas hexadécimale</translation>
    </message>
    <message>
        <source>expected 256 colours: a string of hexadecimal rrggbb, or [[r, g, b], ...] from 0 to 255</source>
        <translation type="vanished">256 couleurs attendues : une chaîne de rrggbb hexadécimaux, ou [[r, g, b], ...] de 0 à 255</translation>
    </message>
    <message>
        <source>expected [r, g, b]</source>
        <translation>[r, g, b] attendu</translation>
    </message>
    <message>
        <source>a channel must be from 0 to 255</source>
        <translation type="vanished">un canal doit être compris entre 0 et 255</translation>
    </message>
    <message>
        <source>expected an xform {&quot;coefs&quot;: [...], &quot;variations&quot;: {...}, &quot;weight&quot;: w, ...}</source>
        <translation>xform attendu {&quot;coefs&quot;: [...], &quot;variations&quot;: {...}, &quot;weight&quot;: w, ...}</translation>
    </message>
    <message>
        <source>a weight must not be negative</source>
        <translation>un poids ne doit pas être négatif</translation>
    </message>
    <message>
        <source>flam3 has no variation of this name</source>
        <translation>flam3 n&apos;a aucune variation de ce nom</translation>
    </message>
    <message>
        <source>no variation of flam3 has this parameter</source>
        <translation>aucune variation de flam3 n&apos;a ce paramètre</translation>
    </message>
    <message>
        <source>a xaos entry must not be negative</source>
        <translation>une entrée xaos ne doit pas être négative</translation>
    </message>
    <message>
        <source>not a field of an xform (coefs, post, variations, parameters, weight, color, color_speed, opacity, animate, chaos, name)</source>
        <translation>pas un champ d&apos;un xform (coefs, post, variations, parameters, weight, color, color_speed, opacity, animate, chaos, name)</translation>
    </message>
    <message>
        <source>Flame</source>
        <translation>Flamme</translation>
    </message>
    <message>
        <source>the scale (pixels per unit) must be positive</source>
        <translation>l&apos;échelle (pixels par unité) doit être positive</translation>
    </message>
    <message>
        <source>a flame is drawn by random iteration only (its maps are not affine): choose random iteration</source>
        <translation>une flamme ne se dessine que par itération aléatoire (ses applications ne sont pas affines) : choisissez l&apos;itération aléatoire</translation>
    </message>
    <message>
        <source>a flame&apos;s xforms carry their own weights (&quot;xforms&quot;): leave the algorithm&apos;s probabilities empty</source>
        <translation>les xforms d&apos;une flamme portent leurs propres poids (&quot;xforms&quot;) : laissez vides les probabilités de l&apos;algorithme</translation>
    </message>
    <message>
        <source>a flame has no subdivision matrices: its maps are not affine</source>
        <translation>une flamme n&apos;a pas de matrices de subdivision : ses applications ne sont pas affines</translation>
    </message>
    <message>
        <source>a fractal flame, drawn by its own chaos game as flam3 draws it; the spectra are those of the xforms&apos; affine (pre) maps, y up</source>
        <translation>une flamme fractale, dessinée par son propre jeu du chaos comme flam3 la dessine ; les spectres sont ceux des applications affines (pre) des xforms, y vers le haut</translation>
    </message>
    <message>
        <source>Change flame of %1</source>
        <translation>Modifier la flamme de %1</translation>
    </message>
    <message>
        <source>Xforms</source>
        <translation>Xforms</translation>
    </message>
    <message>
        <source>flam3&apos;s xforms: {&quot;coefs&quot;: [a, d, b, e, c, f], &quot;variations&quot;: {&quot;linear&quot;: 1, ...}, &quot;weight&quot;: w, &quot;color&quot;: c, ...} each</source>
        <translation>xforms de flam3 : chacun {&quot;coefs&quot;: [a, d, b, e, c, f], &quot;variations&quot;: {&quot;linear&quot;: 1, ...}, &quot;weight&quot;: w, &quot;color&quot;: c, ...}</translation>
    </message>
    <message>
        <source>Final xform</source>
        <translation>Xform finale</translation>
    </message>
    <message>
        <source>Drawn on every point without moving the orbit; null: none</source>
        <translation>Appliqué à chaque point dessiné sans déplacer l&apos;orbite ; null : aucun</translation>
    </message>
    <message>
        <source>Palette</source>
        <translation>Palette</translation>
    </message>
    <message>
        <source>256 colours, indexed by the colour coordinate</source>
        <translation>256 couleurs, indexées par la coordonnée de couleur</translation>
    </message>
    <message>
        <source>Centre x</source>
        <translation>Centre x</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <source>Centre y</source>
        <translation>Centre y</translation>
    </message>
    <message>
        <source>flam3&apos;s: y grows down the picture</source>
        <translation>convention de flam3 : y croît vers le bas de l&apos;image</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Échelle</translation>
    </message>
    <message>
        <source>Pixels per unit (times 2^zoom)</source>
        <translation>Pixels par unité (fois 2^zoom)</translation>
    </message>
    <message>
        <source>Rotation (degrees)</source>
        <translation>Rotation (degrés)</translation>
    </message>
    <message>
        <source>Zoom</source>
        <translation>Zoom</translation>
    </message>
    <message>
        <source>Width (pixels)</source>
        <translation>Largeur (pixels)</translation>
    </message>
    <message>
        <source>Height (pixels)</source>
        <translation>Hauteur (pixels)</translation>
    </message>
    <message>
        <source>Quality (samples per pixel)</source>
        <translation>Qualité (échantillons par pixel)</translation>
    </message>
    <message>
        <source>Tone</source>
        <translation>Tonalité</translation>
    </message>
    <message>
        <source>Brightness</source>
        <translation>Luminosité</translation>
    </message>
    <message>
        <source>Gamma</source>
        <translation>Gamma</translation>
    </message>
    <message>
        <source>Gamma threshold</source>
        <translation>Seuil gamma</translation>
    </message>
    <message>
        <source>Vibrancy</source>
        <translation>Vibrance</translation>
    </message>
    <message>
        <source>Highlight power</source>
        <translation>Puissance des hautes lumières</translation>
    </message>
    <message>
        <source>flam3&apos;s: -1 leaves the highlights as they are</source>
        <translation>convention de flam3 : -1 laisse les hautes lumières telles quelles</translation>
    </message>
    <message>
        <source>expected [r, g, b] from 0 to 1</source>
        <translation>[r, g, b] de 0 à 1 attendu</translation>
    </message>
    <message>
        <source>Background</source>
        <translation>Arrière-plan</translation>
    </message>
    <message>
        <source>[r, g, b] from 0 to 1</source>
        <translation>[r, g, b] de 0 à 1</translation>
    </message>
    <message>
        <source>Supersample</source>
        <translation>Suréchantillonnage</translation>
    </message>
    <message>
        <source>Filter radius (pixels)</source>
        <translation>Rayon du filtre (pixels)</translation>
    </message>
    <message>
        <source>Estimator radius</source>
        <translation>Rayon de l&apos;estimateur</translation>
    </message>
    <message>
        <source>Estimator minimum</source>
        <translation>Minimum de l&apos;estimateur</translation>
    </message>
    <message>
        <source>Estimator curve</source>
        <translation>Courbe de l&apos;estimateur</translation>
    </message>
    <message>
        <source>Fractal flame</source>
        <translation>Flamme fractale</translation>
    </message>
    <message>
        <source>expected 256 colours: a string of hexadecimal rrggbb, or [[r, g, b], ...] from 0 to 1</source>
        <translation>256 couleurs attendues : une chaîne de rrggbb hexadécimaux, ou [[r, g, b], ...] de 0 à 1</translation>
    </message>
    <message>
        <source>a channel must be from 0 to 1</source>
        <translation>un canal doit être compris entre 0 et 1</translation>
    </message>
    <message>
        <source>Gaussian</source>
        <translation>Gaussien</translation>
    </message>
    <message>
        <source>Hermite</source>
        <translation>Hermite</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Boîte</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation>Triangle</translation>
    </message>
    <message>
        <source>Bell</source>
        <translation>Cloche</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-spline</translation>
    </message>
    <message>
        <source>Lanczos 3 (flam3 draws Mitchell)</source>
        <translation>Lanczos 3 (flam3 dessine Mitchell)</translation>
    </message>
    <message>
        <source>Lanczos 2 (flam3 draws Blackman)</source>
        <translation>Lanczos 2 (flam3 dessine Blackman)</translation>
    </message>
    <message>
        <source>Mitchell (flam3 draws Catmull-Rom)</source>
        <translation>Mitchell (flam3 dessine Catmull-Rom)</translation>
    </message>
    <message>
        <source>Blackman (flam3 draws Hanning)</source>
        <translation>Blackman (flam3 dessine Hanning)</translation>
    </message>
    <message>
        <source>Catmull-Rom (flam3 draws Hamming)</source>
        <translation>Catmull-Rom (flam3 dessine Hamming)</translation>
    </message>
    <message>
        <source>Hamming (flam3 draws Lanczos 3)</source>
        <translation>Hamming (flam3 dessine Lanczos 3)</translation>
    </message>
    <message>
        <source>Hanning (flam3 draws Lanczos 2)</source>
        <translation>Hanning (flam3 dessine Lanczos 2)</translation>
    </message>
    <message>
        <source>Quadratic</source>
        <translation>Quadratique</translation>
    </message>
    <message>
        <source>Filter shape</source>
        <translation>Forme du filtre</translation>
    </message>
    <message>
        <source>flam3&apos;s filter_shape; from Lanczos 3 on, flam3 3.1.1 draws another shape than the name says, and so do we</source>
        <translation>filter_shape de flam3 ; à partir de Lanczos 3, flam3 3.1.1 dessine une autre forme que celle que dit le nom, et nous aussi</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Par paliers</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linéaire</translation>
    </message>
    <message>
        <source>Palette mode</source>
        <translation>Mode de palette</translation>
    </message>
    <message>
        <source>flam3&apos;s palette_mode: a hit takes the palette entry at its colour coordinate (step) or between the two entries around it (linear)</source>
        <translation>palette_mode de flam3 : un impact prend l&apos;entrée de la palette à sa coordonnée de couleur (par paliers) ou la couleur entre les deux entrées qui l&apos;entourent (linéaire)</translation>
    </message>
    <message>
        <source>Passes</source>
        <translation>Passes</translation>
    </message>
    <message>
        <source>flam3&apos;s passes: the samples drawn in that many histograms, each log-scaled and density-estimated apart, then summed (a little smoother than one)</source>
        <translation>passes de flam3 : les échantillons tirés dans autant d&apos;histogrammes, chacun mis à l&apos;échelle logarithmique et estimé en densité à part, puis sommés (un peu plus lisse qu&apos;une seule)</translation>
    </message>
</context>
<context>
    <name>awb::FlameXformEditor</name>
    <message>
        <source>The xform to edit; its pre map is its triangle in the attractor view (drag a corner) and in the point table below</source>
        <translation>La transformation (xform) à modifier ; son application initiale est son triangle dans la vue de l&apos;attracteur (faites glisser un coin) et dans le tableau des points ci-dessous</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>A new xform (linear, weight 1) after the others</source>
        <translation>Une nouvelle xform (linéaire, poids 1) après les autres</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Dupliquer</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Weight:</source>
        <translation>Poids :</translation>
    </message>
    <message>
        <source>Colour:</source>
        <translation>Couleur :</translation>
    </message>
    <message>
        <source>Colour speed:</source>
        <translation>Vitesse de couleur :</translation>
    </message>
    <message>
        <source>Opacity:</source>
        <translation>Opacité :</translation>
    </message>
    <message>
        <source>Variation</source>
        <translation>Variation</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Poids</translation>
    </message>
    <message>
        <source>The xform&apos;s variations; a weight of 0 removes one</source>
        <translation>Les variations de la xform ; un poids de 0 en retire une</translation>
    </message>
    <message>
        <source>Add a variation…</source>
        <translation>Ajouter une variation…</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Paramètre</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valeur</translation>
    </message>
    <message>
        <source>The parameters of the xform&apos;s variations</source>
        <translation>Les paramètres des variations de la xform</translation>
    </message>
    <message>
        <source>A flame needs at least one xform.</source>
        <translation>Une flamme a besoin d&apos;au moins une xform.</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation type="vanished">Couleur</translation>
    </message>
    <message>
        <source>Colour speed</source>
        <translation type="vanished">Vitesse de couleur</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation type="vanished">Opacité</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="vanished">%1 : %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1 : « %2 » n&apos;est pas un nombre</translation>
    </message>
    <message>
        <source>Xform %1</source>
        <translation>Xform %1</translation>
    </message>
    <message>
        <source>Xform %1: %2</source>
        <translation>Xform %1 : %2</translation>
    </message>
    <message>
        <source>Final xform</source>
        <translation>Xform finale</translation>
    </message>
</context>
<context>
    <name>awb::FractalItem</name>
    <message>
        <source>expected an array of %1 numbers</source>
        <translation>tableau de %1 nombres attendu</translation>
    </message>
    <message>
        <source>missing (the custom form needs its maps)</source>
        <translation>manquant (la forme personnalisée a besoin de ses applications)</translation>
    </message>
    <message>
        <source>expected a non-empty array of maps {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</source>
        <translation>tableau non vide d’applications {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]} attendu</translation>
    </message>
    <message>
        <source>expected an object with &quot;A&quot; and &quot;b&quot;</source>
        <translation>objet avec &quot;A&quot; et &quot;b&quot; attendu</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>manquant</translation>
    </message>
    <message>
        <source>expected a 2 x 2 matrix [[a11, a12], [a21, a22]]</source>
        <translation type="vanished">matrice 2 x 2 [[a11, a12], [a21, a22]] attendue</translation>
    </message>
    <message>
        <source>the custom form needs at least one map</source>
        <translation>la forme personnalisée demande au moins une application</translation>
    </message>
    <message>
        <source>map %1 is not a map of the plane</source>
        <translation type="vanished">l’application %1 n’est pas une application du plan</translation>
    </message>
    <message>
        <source>map %1 has a non-finite entry</source>
        <translation>l’application %1 a un coefficient non fini</translation>
    </message>
    <message>
        <source>a reference point is not finite</source>
        <translation>un point de référence n’est pas fini</translation>
    </message>
    <message>
        <source>need at least 3 reference points (000 §4), got %1</source>
        <translation>il faut au moins 3 points de référence (000 §4) (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>Fractal</source>
        <translation>Fractale</translation>
    </message>
    <message>
        <source>Change fractal of %1</source>
        <translation>Modifier la fractale de %1</translation>
    </message>
    <message>
        <source>the %1 reference points and the %2 control points must be equally many</source>
        <translation>les %1 points de référence et les %2 points de contrôle doivent être en même nombre</translation>
    </message>
    <message>
        <source>the reference points are ill-conditioned: S_i R differs from f_i(R) by up to %1</source>
        <translation>les points de référence sont mal conditionnés&#xa0;: S_i R diffère de f_i(R) d’au plus %1</translation>
    </message>
    <message>
        <source>Koch curve (000 §4.1)</source>
        <translation>Courbe de Koch (000 §4.1)</translation>
    </message>
    <message>
        <source>Sierpinski triangle (000 §4.2)</source>
        <translation>Triangle de Sierpinski (000 §4.2)</translation>
    </message>
    <message>
        <source>Own maps</source>
        <translation>Applications personnalisées</translation>
    </message>
    <message>
        <source>The presets use the paper&apos;s printed matrices S_i</source>
        <translation>Les préréglages utilisent les matrices S_i imprimées dans l’article</translation>
    </message>
    <message>
        <source>Affine weights</source>
        <translation>Poids affines</translation>
    </message>
    <message>
        <source>Nearest control points</source>
        <translation>Points de contrôle les plus proches</translation>
    </message>
    <message>
        <source>Least norm (all points)</source>
        <translation>Norme minimale (tous les points)</translation>
    </message>
    <message>
        <source>How f_i(P_j) is written as an affine combination of the control points (000 eq. (5)): nearest points keep edits local, least norm lets every point move the whole fractal</source>
        <translation>Manière d’écrire f_i(P_j) comme combinaison affine des points de contrôle (000 éq. (5))&#xa0;: les points les plus proches gardent les modifications locales, la norme minimale laisse chaque point déplacer toute la fractale</translation>
    </message>
    <message>
        <source>Fractal with control points</source>
        <translation>Fractale à points de contrôle</translation>
    </message>
    <message>
        <source>expected a 2 x 2 matrix [[a11, a12], [a21, a22]] or a 3 x 3 one</source>
        <translation>matrice 2 x 2 [[a11, a12], [a21, a22]] ou 3 x 3 attendue</translation>
    </message>
    <message>
        <source>expected a %1 x %1 matrix, as the first map</source>
        <translation>matrice %1 x %1 attendue, comme pour la première application</translation>
    </message>
    <message>
        <source>map %1 is not a map of the plane or of space like the first</source>
        <translation>l’application %1 n’est pas une application du plan ou de l’espace de même dimension que la première</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>Applications</translation>
    </message>
    <message>
        <source>x ↦ x A + b: {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]} each, or 3 x 3 and 3 numbers in space</source>
        <translation>x ↦ x A + b&#xa0;: chacune sous la forme {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}, ou 3 x 3 et 3 nombres dans l’espace</translation>
    </message>
    <message>
        <source>Reference points</source>
        <translation>Points de référence</translation>
    </message>
    <message>
        <source>The points the S_i are built for (S_i R = f_i(R)); none: the control points themselves</source>
        <translation>Les points pour lesquels les S_i sont construites (S_i R = f_i(R))&#x202f;; aucun&#xa0;: les points de contrôle eux-mêmes</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Points de contrôle</translation>
    </message>
    <message>
        <source>%1 maps: at most %2 maps are supported</source>
        <translation>%1 applications : au plus %2 applications sont prises en charge</translation>
    </message>
</context>
<context>
    <name>awb::IfsExchange</name>
    <message>
        <source>%1, line %2: entry %3: %4 (%5)</source>
        <translation>%1, ligne %2&#xa0;: entrée %3&#xa0;: %4 (%5)</translation>
    </message>
    <message>
        <source>%1, line %2: %3</source>
        <translation>%1, ligne %2&#xa0;: %3</translation>
    </message>
    <message>
        <source>%1: the file is larger than %2 MB</source>
        <translation>%1&#xa0;: le fichier dépasse %2 Mo</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>impossible de lire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>%1 cannot be computed: %2</source>
        <translation>%1 ne peut pas être calculé&#xa0;: %2</translation>
    </message>
    <message>
        <source>the IFS of %1 acts in a space of dimension %2 that is drawn through a projection (000 §2): a Fractint entry holds maps of the plane or of space only</source>
        <translation type="vanished">l’IFS de %1 agit dans un espace de dimension %2 qui est tracé au moyen d’une projection (000 §2)&#xa0;: une entrée Fractint ne contient que des applications du plan ou de l’espace</translation>
    </message>
    <message>
        <source>the IFS of %1 acts in a space of dimension %2 that is drawn through a projection (000 §2), and its maps do not act on the drawn coordinates alone: %3 holds maps of the plane or of space only</source>
        <translation>l&apos;IFS de %1 agit dans un espace de dimension %2 dessiné par une projection (000 §2), et ses applications n&apos;agissent pas sur les seules coordonnées dessinées : %3 ne contient que des applications du plan ou de l&apos;espace</translation>
    </message>
    <message>
        <source>%1 is a fractal flame: its xforms are not affine maps, and %2 holds affine maps only (export it as a flam3 flame)</source>
        <translation>%1 est une flamme fractale : ses xforms ne sont pas des applications affines, et %2 ne contient que des applications affines (exportez-la comme flamme flam3)</translation>
    </message>
</context>
<context>
    <name>awb::InsertControlPointCommand</name>
    <message>
        <source>Add a control point to %1</source>
        <translation>Ajouter un point de contrôle à %1</translation>
    </message>
</context>
<context>
    <name>awb::InsertItemCommand</name>
    <message>
        <source>Add %1</source>
        <translation>Ajouter %1</translation>
    </message>
</context>
<context>
    <name>awb::Item</name>
    <message>
        <source>Rename</source>
        <translation>Renommer</translation>
    </message>
    <message>
        <source>Change style of %1</source>
        <translation>Modifier le style de %1</translation>
    </message>
    <message>
        <source>Edit animation of %1</source>
        <translation>Modifier l’animation de %1</translation>
    </message>
    <message>
        <source>the name cannot be empty</source>
        <translation>le nom ne peut pas être vide</translation>
    </message>
    <message>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 n’a pas de paramètre «&#xa0;%2&#xa0;»</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid value for %2</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas une valeur valide pour %2</translation>
    </message>
    <message>
        <source>circular reference</source>
        <translation>référence circulaire</translation>
    </message>
    <message>
        <source>there is not enough memory to compute it</source>
        <translation>la mémoire est insuffisante pour le calculer</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>By map</source>
        <translation>Par application</translation>
    </message>
    <message>
        <source>By address prefix</source>
        <translation>Par préfixe d’adresse</translation>
    </message>
    <message>
        <source>Single colour</source>
        <translation>Couleur unique</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Couleur</translation>
    </message>
    <message>
        <source>Style</source>
        <translation>Style</translation>
    </message>
    <message>
        <source>The attractor&apos;s colours: by the map that made each point, by the first symbols of its address, or one colour</source>
        <translation>Les couleurs de l’attracteur&#xa0;: selon l’application qui a produit chaque point, selon les premiers symboles de son adresse, ou une seule couleur</translation>
    </message>
    <message>
        <source>Prefix length</source>
        <translation>Longueur du préfixe</translation>
    </message>
    <message>
        <source>Colour by address: how many of its first symbols pick the colour</source>
        <translation>Couleur par adresse&#xa0;: nombre de premiers symboles de l’adresse qui déterminent la couleur</translation>
    </message>
    <message>
        <source>Point size</source>
        <translation>Taille des points</translation>
    </message>
    <message>
        <source>Points of the attractor, in pixels</source>
        <translation>Taille des points de l’attracteur, en pixels</translation>
    </message>
    <message>
        <source>expected an array of &quot;#rrggbb&quot; strings</source>
        <translation>tableau de chaînes &quot;#rrggbb&quot; attendu</translation>
    </message>
    <message>
        <source>expected a string &quot;#rrggbb&quot;</source>
        <translation>chaîne &quot;#rrggbb&quot; attendue</translation>
    </message>
    <message>
        <source>Palette</source>
        <translation>Palette</translation>
    </message>
    <message>
        <source>Own colours, one per map or address prefix (&quot;#rrggbb&quot;); none: the views&apos; palette</source>
        <translation>Couleurs personnalisées, une par application ou préfixe d’adresse (&quot;#rrggbb&quot;)&#x202f;; aucune&#xa0;: la palette des vues</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatique</translation>
    </message>
    <message>
        <source>Hits</source>
        <translation>Impacts</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>Densité</translation>
    </message>
    <message>
        <source>Tone</source>
        <translation>Tonalité</translation>
    </message>
    <message>
        <source>Hits: every pixel the attractor reaches (the papers&apos; look); density: the invariant measure by log density; automatic: hits for deterministic, density for random iteration</source>
        <translation>Impacts&#xa0;: chaque pixel atteint par l’attracteur (l’aspect des articles)&#x202f;; densité&#xa0;: la mesure invariante en densité logarithmique&#x202f;; automatique&#xa0;: impacts pour l’itération déterministe, densité pour l’itération aléatoire</translation>
    </message>
    <message>
        <source>Gamma</source>
        <translation>Gamma</translation>
    </message>
    <message>
        <source>Gamma of the density tone</source>
        <translation>Gamma du rendu en densité</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animation</translation>
    </message>
    <message>
        <source>%1 is outside the range from %2 to %3</source>
        <translation>%1 est hors de l’intervalle de %2 à %3</translation>
    </message>
    <message>
        <source>%1 must be a finite number</source>
        <translation>%1 doit être un nombre fini</translation>
    </message>
    <message>
        <source>%1 must be at least %2 and at most %3, not %4</source>
        <translation>%1 doit valoir au moins %2 et au plus %3, et non %4</translation>
    </message>
    <message>
        <source>%1 must be at least %2, not %3</source>
        <translation>%1 doit valoir au moins %2, et non %3</translation>
    </message>
    <message>
        <source>%1 must be at most %2, not %3</source>
        <translation>%1 doit valoir au plus %2, et non %3</translation>
    </message>
    <message>
        <source>expected [re, im] or a number</source>
        <translation>[re, im] ou nombre attendu</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not %3</source>
        <translation>%1&#xa0;: «&#xa0;%2&#xa0;» n’est pas %3</translation>
    </message>
    <message>
        <source>a JSON value (%1)</source>
        <translation>une valeur JSON (%1)</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>un nombre</translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation>un nombre entier</translation>
    </message>
    <message>
        <source>one of %1 (or its number from 0)</source>
        <translation>l’une des valeurs %1 (ou son numéro à partir de 0)</translation>
    </message>
    <message>
        <source>a complex number (&quot;0.5,0.3&quot; or &quot;0.5+0.3i&quot;)</source>
        <translation>un nombre complexe (&quot;0.5,0.3&quot; ou &quot;0.5+0.3i&quot;)</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true ou false</translation>
    </message>
    <message>
        <source>an item&apos;s type cannot change (%1 to %2): add a new item</source>
        <translation>le type d’un élément ne peut pas changer (%1 en %2)&#xa0;: ajoutez un nouvel élément</translation>
    </message>
    <message>
        <source>children are items of their own: add, remove or update them</source>
        <translation>les éléments enfants sont des éléments à part entière&#xa0;: ajoutez-les, supprimez-les ou mettez-les à jour séparément</translation>
    </message>
    <message>
        <source>Update %1</source>
        <translation>Mettre à jour %1</translation>
    </message>
    <message>
        <source>%1 is shown, not edited</source>
        <translation>%1&#xa0;: affichage seul, non modifiable</translation>
    </message>
    <message>
        <source>Change %1 of %2</source>
        <translation>Modifier %1 de %2</translation>
    </message>
</context>
<context>
    <name>awb::ItemAddress</name>
    <message>
        <source>t: the B-spline&apos;s knot parameter scaled to [0, 1] (the address in base 2)</source>
        <translation>t&#xa0;: paramètre nodal de la B-spline ramené à [0, 1] (l’adresse en base 2)</translation>
    </message>
    <message>
        <source>t: the knot parameter scaled to [0, 1] (the address in base 2)</source>
        <translation>t&#xa0;: paramètre nodal ramené à [0, 1] (l’adresse en base 2)</translation>
    </message>
    <message>
        <source>t: the Bernstein parameter (the address in base 2)</source>
        <translation>t&#xa0;: paramètre de Bernstein (l’adresse en base 2)</translation>
    </message>
    <message>
        <source>t: the Bernstein parameter (pieces [0, t], [t, 1] of the split)</source>
        <translation>t&#xa0;: paramètre de Bernstein (morceaux [0, t] et [t, 1] de la découpe)</translation>
    </message>
    <message>
        <source>t: the scheme&apos;s own parameter, the address read in base %1</source>
        <translation>t&#xa0;: paramètre propre au schéma, l’adresse lue en base %1</translation>
    </message>
    <message>
        <source>this item is drawn by an automaton: its words are not addresses of one IFS</source>
        <translation>cet élément est tracé par un automate&#xa0;: ses mots ne sont pas des adresses d’un seul IFS</translation>
    </message>
    <message>
        <source>a parameter interval is [t0, t1] with two numbers, e.g. [0.25, 0.5]</source>
        <translation>un intervalle de paramètre [t0, t1] comporte deux nombres, p. ex. [0.25, 0.5]</translation>
    </message>
    <message>
        <source>the parameter interval [%1, %2] must satisfy 0 &lt;= t0 &lt; t1 &lt;= 1</source>
        <translation>l’intervalle de paramètre [%1, %2] doit vérifier 0 &lt;= t0 &lt; t1 &lt;= 1</translation>
    </message>
</context>
<context>
    <name>awb::ItemAnalysis</name>
    <message>
        <source>not measured: the flame&apos;s maps are not their affine parts, whose attractor the analysis would count</source>
        <translation>non mesurée : les applications de la flamme ne sont pas leurs parties affines, dont l&apos;analyse compterait l&apos;attracteur</translation>
    </message>
</context>
<context>
    <name>awb::ItemController</name>
    <message>
        <source>%1 shows nothing: %2</source>
        <translation>%1 n’affiche rien&#xa0;: %2</translation>
    </message>
    <message>
        <source>%1 has no attractor to draw.</source>
        <translation>%1 n’a pas d’attracteur à tracer.</translation>
    </message>
    <message>
        <source>%1 cannot be drawn: %2</source>
        <translation>%1 ne peut pas être tracé&#xa0;: %2</translation>
    </message>
    <message>
        <source>Regularity: only for subdivision curves</source>
        <translation>Régularité&#xa0;: uniquement pour les courbes de subdivision</translation>
    </message>
    <message>
        <source>Regularity: does not apply (%1)</source>
        <translation type="vanished">Régularité&#xa0;: sans objet (%1)</translation>
    </message>
    <message>
        <source>complex de Casteljau parameter</source>
        <translation type="vanished">paramètre de de Casteljau complexe</translation>
    </message>
    <message>
        <source>the scheme&apos;s parameters are refused</source>
        <translation type="vanished">les paramètres du schéma sont refusés</translation>
    </message>
    <message>
        <source>Changing %1 (%2, %3) from %4 to %5 makes row %2 sum to %6, not 1: the rows of a subdivision matrix are affine combinations.

Take the difference %7 from the entry in column %8 (%9 → %10) so that the row sums to 1?</source>
        <translation>Changer %1 (%2, %3) de %4 à %5 donne à la ligne %2 la somme %6, et non 1&#xa0;: les lignes d’une matrice de subdivision sont des combinaisons affines.

Retrancher la différence %7 du coefficient de la colonne %8 (%9 → %10) pour que la somme de la ligne vaille 1&#x202f;?</translation>
    </message>
    <message>
        <source>%1 (%2, %3) = %4 was refused: %5</source>
        <translation>%1 (%2, %3) = %4 a été refusé&#xa0;: %5</translation>
    </message>
    <message>
        <source>Insert Point &amp;Before %1</source>
        <translation>Insérer un point &amp;avant %1</translation>
    </message>
    <message>
        <source>Insert Point &amp;After %1</source>
        <translation>Insérer un point a&amp;près %1</translation>
    </message>
    <message>
        <source>&amp;Delete Point %1</source>
        <translation>&amp;Supprimer le point %1</translation>
    </message>
    <message>
        <source>&amp;Insert Point Here</source>
        <translation>&amp;Insérer un point ici</translation>
    </message>
    <message>
        <source>&amp;Append Point Here</source>
        <translation>&amp;Ajouter un point ici</translation>
    </message>
    <message>
        <source>&amp;Fit View</source>
        <translation>A&amp;juster la vue</translation>
    </message>
    <message>
        <source>Fᵏ(X₀)</source>
        <translation>Fᵏ(X₀)</translation>
    </message>
    <message>
        <source>Fᵏ(X₀) to the %1</source>
        <translation>Fᵏ(X₀) jusqu’à la %1</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>sommet %1</translation>
    </message>
    <message>
        <source>the centre of face %1</source>
        <translation>centre de la face %1</translation>
    </message>
    <message>
        <source>S at %1 (n = %2)</source>
        <translation>S (%1, n = %2)</translation>
    </message>
    <message>
        <source>The Vertex tab analyses the extraordinary vertices of a mesh surface (Item &gt; Add &gt; Mesh surface, File &gt; Import Mesh).</source>
        <translation>L’onglet Sommet analyse les sommets extraordinaires d’une surface de maillage (Élément &gt; Ajouter &gt; Surface de maillage, Fichier &gt; Importer un maillage).</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 de %2</translation>
    </message>
    <message>
        <source>Eigenvalues at %1</source>
        <translation>Valeurs propres (%1)</translation>
    </message>
    <message>
        <source>%1 cannot be removed: an IFS of own matrices needs at least two maps</source>
        <translation>%1 ne peut pas être supprimée&#xa0;: un IFS de matrices personnelles nécessite au moins deux applications</translation>
    </message>
    <message>
        <source>No map was added: %1</source>
        <translation>Aucune application n&apos;a été ajoutée&#xa0;: %1</translation>
    </message>
    <message>
        <source>No map was removed: %1</source>
        <translation>Aucune application n&apos;a été supprimée&#xa0;: %1</translation>
    </message>
    <message>
        <source>Save Regularity Certificate</source>
        <translation>Enregistrer le certificat de régularité</translation>
    </message>
    <message>
        <source>Regularity certificate (*.json)</source>
        <translation>Certificat de régularité (*.json)</translation>
    </message>
    <message>
        <source>No certificate: the regularity of the current curve is not computed yet.</source>
        <translation>Aucun certificat&#xa0;: la régularité de la courbe courante n&apos;est pas encore calculée.</translation>
    </message>
    <message>
        <source>No certificate was saved: %1</source>
        <translation>Aucun certificat n&apos;a été enregistré&#xa0;: %1</translation>
    </message>
    <message>
        <source>Saved the regularity certificate to %1</source>
        <translation>Certificat de régularité enregistré dans %1</translation>
    </message>
</context>
<context>
    <name>awb::ItemFigure</name>
    <message>
        <source>the 16-bit density is written to PNG files, got &apos;%1&apos;</source>
        <translation>la densité 16 bits s’écrit dans des fichiers PNG, reçu « %1 »</translation>
    </message>
    <message>
        <source>the raw density (.exr, 16-bit PNG) counts an attractor&apos;s points; this item&apos;s figure is a polygon</source>
        <translation>la densité brute (.exr, PNG 16 bits) compte les points d’un attracteur ; la figure de cet élément est un polygone</translation>
    </message>
    <message>
        <source>the rendering was cancelled</source>
        <translation>le rendu a été annulé</translation>
    </message>
    <message>
        <source>item &apos;%1&apos;: %2</source>
        <translation>élément «&#xa0;%1&#xa0;»&#xa0;: %2</translation>
    </message>
    <message>
        <source>depth %1 makes %2 images; at most 4e9 are rendered</source>
        <translation>la profondeur %1 produit %2 images&#x202f;; 4e9 au plus sont rendues</translation>
    </message>
    <message>
        <source>the raw density (.exr, 16-bit PNG) is of attractors drawn in the plane; &apos;%1&apos; is drawn in space</source>
        <translation>la densité brute (.exr, PNG 16 bits) concerne les attracteurs tracés dans le plan ; « %1 » est tracé dans l’espace</translation>
    </message>
    <message>
        <source>the view must be azimuth and elevation in degrees with |elevation| &lt;= 90, got %1, %2</source>
        <translation>la vue doit être un azimut et une élévation en degrés avec |élévation| &lt;= 90, reçu %1, %2</translation>
    </message>
    <message>
        <source>%1 random points</source>
        <translation>%1 points aléatoires</translation>
    </message>
    <message>
        <source>F^%1(X0)</source>
        <translation>F^%1(X0)</translation>
    </message>
    <message>
        <source>, maps %1 of %2</source>
        <translation>, applications %1 sur %2</translation>
    </message>
    <message>
        <source>%1: %2%3 — orthographic view from azimuth %4°, elevation %5°</source>
        <translation>%1&#xa0;: %2%3 — vue orthographique depuis l’azimut %4°, élévation %5°</translation>
    </message>
    <message>
        <source>%1: %2 random points</source>
        <translation>%1&#xa0;: %2 points aléatoires</translation>
    </message>
    <message>
        <source>%1: F^%2(X0)</source>
        <translation>%1&#xa0;: F^%2(X0)</translation>
    </message>
    <message>
        <source>%1: polygon after %2 steps</source>
        <translation>%1&#xa0;: polygone après %2 étapes</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is drawn by random iteration only (its maps are not affine): give --samples, not --depth</source>
        <translation>l&apos;élément « %1 » ne se dessine que par itération aléatoire (ses applications ne sont pas affines) : donnez --samples, pas --depth</translation>
    </message>
    <message>
        <source>give --bounds: the item has no frame of its own</source>
        <translation>donnez --bounds : l&apos;élément n&apos;a pas de cadre propre</translation>
    </message>
    <message>
        <source>%1 samples; at most %2</source>
        <translation>%1 échantillons ; au plus %2</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation type="vanished">impossible d&apos;écrire %1</translation>
    </message>
</context>
<context>
    <name>awb::JunctionSpec</name>
    <message>
        <source>the junction parameter %1 must be a finite number</source>
        <translation>le paramètre de jonction %1 doit être un nombre fini</translation>
    </message>
    <message>
        <source>%1 = %2 is outside (%3, %4): %5</source>
        <translation>%1 = %2 est hors de (%3, %4)&#xa0;: %5</translation>
    </message>
</context>
<context>
    <name>awb::MainWindow</name>
    <message>
        <source>Attractor Workbench projects (*.awb);;All files (*)</source>
        <translation>Projets Attractor Workbench (*.awb);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Échec de l’enregistrement automatique&#xa0;: %1</translation>
    </message>
    <message>
        <source>&lt;original&gt;</source>
        <translation>&lt;version d’origine&gt;</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Cancel the analysis</source>
        <translation>Annuler l’analyse</translation>
    </message>
    <message>
        <source>Drawing %p%</source>
        <translation>Tracé %p&#xa0;%</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêter</translation>
    </message>
    <message>
        <source>Stop drawing the attractor (Esc); F5 draws it again</source>
        <translation>Arrêter le tracé de l’attracteur (Échap)&#x202f;; F5 le relance</translation>
    </message>
    <message>
        <source>Drawing the attractor for the figure…</source>
        <translation>Tracé de l’attracteur pour la figure…</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>Figure</translation>
    </message>
    <message>
        <source>Drawing stopped; press F5 to draw again.</source>
        <translation>Tracé interrompu&#x202f;; appuyez sur F5 pour le relancer.</translation>
    </message>
    <message>
        <source>Analysis %p%</source>
        <translation>Analyse %p&#xa0;%</translation>
    </message>
    <message>
        <source>Analysis cancelled.</source>
        <translation>Analyse annulée.</translation>
    </message>
    <message>
        <source>Row sum</source>
        <translation>Somme de ligne</translation>
    </message>
    <message>
        <source>Edit refused</source>
        <translation>Modification refusée</translation>
    </message>
    <message>
        <source>x = %1, y = %2</source>
        <translation>x = %1, y = %2</translation>
    </message>
    <message>
        <source>Drawing failed: %1</source>
        <translation>Échec du tracé&#xa0;: %1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nouveau</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Ouvrir…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Enregistrer &amp;sous…</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>Re&amp;venir à la version enregistrée</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Fermer</translation>
    </message>
    <message>
        <source>&amp;Print…</source>
        <translation>&amp;Imprimer…</translation>
    </message>
    <message>
        <source>Print Pre&amp;view…</source>
        <translation>&amp;Aperçu avant impression…</translation>
    </message>
    <message>
        <source>Ctrl+Alt+P</source>
        <translation>Ctrl+Alt+P</translation>
    </message>
    <message>
        <source>Print to P&amp;DF…</source>
        <translation>Imprimer en P&amp;DF…</translation>
    </message>
    <message>
        <source>Print to PDF</source>
        <translation>Imprimer en PDF</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Document PDF (*.pdf)</translation>
    </message>
    <message>
        <source>&amp;Export Figure…</source>
        <translation>E&amp;xporter la figure…</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Export &amp;Points…</source>
        <translation>Exporter les &amp;points…</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>Pre&amp;ferences…</source>
        <translation>&amp;Préférences…</translation>
    </message>
    <message>
        <source>Copy Matrices as &amp;LaTeX</source>
        <translation>Copier les matrices en &amp;LaTeX</translation>
    </message>
    <message>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <source>The current item has no matrices.</source>
        <translation>L’élément courant n’a pas de matrices.</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n matrices as LaTeX (amsmath bmatrix).</source>
        <translation>
            <numerusform>%n matrice copiée en LaTeX (amsmath bmatrix).</numerusform>
            <numerusform>%n matrices copiées en LaTeX (amsmath bmatrix).</numerusform>
        </translation>
    </message>
    <message>
        <source>D&amp;uplicate Item</source>
        <translation>D&amp;upliquer l’élément</translation>
    </message>
    <message>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <source>&amp;Delete Item</source>
        <translation>&amp;Supprimer l’élément</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>Zoom a&amp;vant</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Zoom a&amp;rrière</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>A&amp;juster</translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <source>&amp;Stop Drawing</source>
        <translation>&amp;Interrompre le tracé</translation>
    </message>
    <message>
        <source>&amp;Draw Again</source>
        <translation>Re&amp;dessiner</translation>
    </message>
    <message>
        <source>&amp;Play/Pause Animation</source>
        <translation>&amp;Lecture/pause de l’animation</translation>
    </message>
    <message>
        <source>S&amp;top Animation</source>
        <translation>Arrê&amp;ter l’animation</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>Réinitialiser la dispositi&amp;on</translation>
    </message>
    <message>
        <source>&amp;About Attractor Workbench</source>
        <translation>À &amp;propos d’Attractor Workbench</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>À propos de &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Guide de l’utilisateur</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Rétablir</translation>
    </message>
    <message>
        <source>Nothing to %1 (%2)</source>
        <translation>Rien à %1 (%2)</translation>
    </message>
    <message>
        <source>%1 %2 (%3)</source>
        <translation>%1 %2 (%3)</translation>
    </message>
    <message>
        <source>&amp;Control Polygon</source>
        <translation>Polygone de &amp;contrôle</translation>
    </message>
    <message>
        <source>Control &amp;Net (3D)</source>
        <translation>Ré&amp;seau de contrôle (3D)</translation>
    </message>
    <message>
        <source>Subdivided &amp;Mesh (3D)</source>
        <translation>&amp;Maillage subdivisé (3D)</translation>
    </message>
    <message>
        <source>&amp;Attractor (3D)</source>
        <translation>&amp;Attracteur (3D)</translation>
    </message>
    <message>
        <source>A&amp;xes (3D)</source>
        <translation>A&amp;xes (3D)</translation>
    </message>
    <message>
        <source>&amp;Bounding Box (3D)</source>
        <translation>&amp;Boîte englobante (3D)</translation>
    </message>
    <message>
        <source>&amp;Perspective (3D)</source>
        <translation>&amp;Perspective (3D)</translation>
    </message>
    <message>
        <source>&amp;Start Set</source>
        <translation>Ensemble i&amp;nitial</translation>
    </message>
    <message>
        <source>&amp;Exact Curve</source>
        <translation>Courbe &amp;exacte</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>&amp;Grille</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>Projet</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <source>Undo History</source>
        <translation>Historique des modifications</translation>
    </message>
    <message>
        <source>Spectrum</source>
        <translation>Spectre</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>Matrices</translation>
    </message>
    <message>
        <source>Analysis</source>
        <translation>Analyse</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animation</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Ouvrir un fichier &amp;récent</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>&amp;Item</source>
        <translation>É&amp;lément</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>&amp;Ajouter</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>Four-point &amp;Regularity Chart…</source>
        <translation>Graphique de régularité du schéma à &amp;quatre points…</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Aid&amp;e</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Principale</translation>
    </message>
    <message>
        <source> Hutchinson step: </source>
        <translation> Étape de Hutchinson&#xa0;: </translation>
    </message>
    <message>
        <source>off</source>
        <translation>désactivé</translation>
    </message>
    <message>
        <source>  Subdivision steps: </source>
        <translation>  Étapes de subdivision&#xa0;: </translation>
    </message>
    <message>
        <source>Classic subdivision polygons beside the IFS attractor</source>
        <translation>Polygones de subdivision classique à côté de l’attracteur de l’IFS</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <source>%1[*] — Attractor Workbench</source>
        <translation>%1[*] — Attractor Workbench</translation>
    </message>
    <message>
        <source>Cubic B-spline</source>
        <translation>B-spline cubique</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Ouvrir un projet</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Ouvert&#xa0;: %1</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Enregistrer le projet</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Enregistré&#xa0;: %1</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Modifications non enregistrées</translation>
    </message>
    <message>
        <source>The project &quot;%1&quot; has unsaved changes. Save them?</source>
        <translation>Le projet «&#xa0;%1&#xa0;» contient des modifications non enregistrées. Voulez-vous les enregistrer&#x202f;?</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Enregistrer le projet sous</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Revenir à la version enregistrée</translation>
    </message>
    <message>
        <source>Discard all changes and reload %1?</source>
        <translation>Abandonner toutes les modifications et recharger %1&#x202f;?</translation>
    </message>
    <message>
        <source>Printing cancelled.</source>
        <translation>Impression annulée.</translation>
    </message>
    <message>
        <source>Print</source>
        <translation>Imprimer</translation>
    </message>
    <message>
        <source>The printer could not be started.</source>
        <translation>L’imprimante n’a pas pu être démarrée.</translation>
    </message>
    <message>
        <source>A .tex file holds the matrices only: choose the Matrices view, or .png, .svg or .pdf for a picture.</source>
        <translation>Un fichier .tex ne contient que les matrices&#xa0;: choisissez la vue Matrices, ou bien .png, .svg ou .pdf pour une image.</translation>
    </message>
    <message>
        <source>The current item has no matrices to export.</source>
        <translation>L’élément courant n’a pas de matrices à exporter.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>Impossible d’écrire %1&#xa0;: %2.</translation>
    </message>
    <message>
        <source>Unknown format &quot;%1&quot;: use .png, .svg or .pdf (.tex for the matrices).</source>
        <translation type="vanished">Format «&#xa0;%1&#xa0;» inconnu&#xa0;: utilisez .png, .svg ou .pdf (.tex pour les matrices).</translation>
    </message>
    <message>
        <source>Exporting %1 was cancelled while the attractor was drawn.</source>
        <translation>L’exportation de %1 a été annulée pendant le tracé de l’attracteur.</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="vanished">Exporté&#xa0;: %1</translation>
    </message>
    <message>
        <source>About Attractor Workbench</source>
        <translation>À propos d’Attractor Workbench</translation>
    </message>
    <message>
        <source>Attractor Workbench %1

Subdivision curves as attractors of iterated function systems: control points, subdivision matrices, spectra and figures.</source>
        <translation>Attractor Workbench %1

Les courbes de subdivision comme attracteurs de systèmes de fonctions itérées&#xa0;: points de contrôle, matrices de subdivision, spectres et figures.</translation>
    </message>
    <message>
        <source>Spectra of %1</source>
        <translation>Spectres de %1</translation>
    </message>
    <message>
        <source>Bicubic B-spline</source>
        <translation>B-spline bicubique</translation>
    </message>
    <message>
        <source>Loop (box spline)</source>
        <translation>Loop (box-spline)</translation>
    </message>
    <message>
        <source>Kobbelt √3</source>
        <translation>Kobbelt √3</translation>
    </message>
    <message>
        <source>%1, %2 layout</source>
        <translation>%1, disposition %2</translation>
    </message>
    <message>
        <source>%1 surface</source>
        <translation>Surface %1</translation>
    </message>
    <message>
        <source>duplicate</source>
        <translation>duplication</translation>
    </message>
    <message>
        <source>Duplicate Item</source>
        <translation>Dupliquer l’élément</translation>
    </message>
    <message>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <source>an unsaved project</source>
        <translation>un projet non enregistré</translation>
    </message>
    <message>
        <source>Recover Project</source>
        <translation>Récupérer le projet</translation>
    </message>
    <message>
        <source>Attractor Workbench did not shut down properly. A recovery copy of %1 from %2 exists. Recover it? (Discard deletes the copy.)</source>
        <translation>Attractor Workbench ne s’est pas fermé correctement. Il existe une copie de récupération de %1 datant du %2. Voulez-vous la récupérer&#x202f;? (Si vous l’abandonnez, la copie est supprimée.)</translation>
    </message>
    <message>
        <source>The recovery copy cannot be read: %1</source>
        <translation>La copie de récupération est illisible&#xa0;: %1</translation>
    </message>
    <message>
        <source>The recovery copy cannot be read: %1

It was kept as %2.</source>
        <translation>La copie de récupération est illisible&#xa0;: %1

Elle a été conservée sous le nom %2.</translation>
    </message>
    <message>
        <source>Export Points</source>
        <translation>Exporter les points</translation>
    </message>
    <message>
        <source>The current item has no attractor whose points could be exported.</source>
        <translation>L’élément courant n’a pas d’attracteur dont les points pourraient être exportés.</translation>
    </message>
    <message>
        <source>Exported the points to %1</source>
        <translation>Points exportés vers %1</translation>
    </message>
    <message>
        <source>The current item has no attractor.</source>
        <translation>L’élément courant n’a pas d’attracteur.</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <source>System Default</source>
        <translation>Langue du système</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Langue</translation>
    </message>
    <message>
        <source>The language changes when Attractor Workbench is started again.</source>
        <translation>Le changement de langue prendra effet au prochain démarrage d’Attractor Workbench.</translation>
    </message>
    <message>
        <source>Built with Qt %1 (running on Qt %2), Eigen %3 and QCustomPlot %4.</source>
        <translation>Compilé avec Qt %1 (exécuté avec Qt %2), Eigen %3 et QCustomPlot %4.</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>Open E&amp;xample</source>
        <translation>Ouvrir un e&amp;xemple</translation>
    </message>
    <message>
        <source>Draw Fᵏ(X₀) of the start set X₀ as vectors</source>
        <translation>Dessiner Fᵏ(X₀) de l’ensemble initial X₀ en vecteurs</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>sans-titre</translation>
    </message>
    <message>
        <source>No examples installed</source>
        <translation>Aucun exemple installé</translation>
    </message>
    <message>
        <source>Open Example</source>
        <translation>Ouvrir un exemple</translation>
    </message>
    <message>
        <source>Opened the example %1 (a copy: Save As keeps it)</source>
        <translation>Exemple %1 ouvert (une copie : « Enregistrer sous » la conserve)</translation>
    </message>
    <message>
        <source>Projects and figures with their item (*.awb *.png *.svg);;Attractor Workbench projects (*.awb);;Exported figures (*.png *.svg);;All files (*)</source>
        <translation type="vanished">Projets et figures avec leur élément (*.awb *.png *.svg);;Projets Attractor Workbench (*.awb);;Figures exportées (*.png *.svg);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>&amp;Import Mesh…</source>
        <translation>&amp;Importer un maillage…</translation>
    </message>
    <message>
        <source>Import Mesh</source>
        <translation>Importer un maillage</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.off *.ply);;Wavefront OBJ (*.obj);;OFF (*.off);;PLY (*.ply)</source>
        <translation>Maillages (*.obj *.off *.ply);;Wavefront OBJ (*.obj);;OFF (*.off);;PLY (*.ply)</translation>
    </message>
    <message>
        <source>Catmull–Clark (any polygons)</source>
        <translation>Catmull–Clark (tous polygones)</translation>
    </message>
    <message>
        <source>Loop (triangles only)</source>
        <translation>Loop (triangles uniquement)</translation>
    </message>
    <message>
        <source>Subdivision scheme:</source>
        <translation>Schéma de subdivision&#xa0;:</translation>
    </message>
    <message>
        <source>Cube (Catmull–Clark)</source>
        <translation>Cube (Catmull–Clark)</translation>
    </message>
    <message>
        <source>Tetrahedron (Loop)</source>
        <translation>Tétraèdre (Loop)</translation>
    </message>
    <message>
        <source>Octahedron (Loop)</source>
        <translation>Octaèdre (Loop)</translation>
    </message>
    <message>
        <source>Icosahedron (Loop)</source>
        <translation>Icosaèdre (Loop)</translation>
    </message>
    <message>
        <source>Pentagonal prism (Catmull–Clark)</source>
        <translation>Prisme pentagonal (Catmull–Clark)</translation>
    </message>
    <message>
        <source>Open grid (Catmull–Clark)</source>
        <translation>Grille ouverte (Catmull–Clark)</translation>
    </message>
    <message>
        <source>Grid of mixed diagonals (Loop)</source>
        <translation>Grille à diagonales mêlées (Loop)</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Sommet</translation>
    </message>
    <message>
        <source>Valences</source>
        <translation>Valences</translation>
    </message>
    <message>
        <source>%1: its spectrum, verdict and characteristic map are in the Spectrum, Matrices and Analysis docks</source>
        <translation>%1&#xa0;: son spectre, le verdict et l’application caractéristique sont dans les panneaux Spectre, Matrices et Analyse</translation>
    </message>
    <message>
        <source>Export &amp;Mesh…</source>
        <translation>Exporter le &amp;maillage…</translation>
    </message>
    <message>
        <source>Export Mesh writes a mesh surface; %1 is a %2</source>
        <translation>«&#xa0;Exporter le maillage&#xa0;» écrit une surface de maillage&#x202f;; %1 est de type %2</translation>
    </message>
    <message>
        <source>Export Mesh writes a mesh surface: choose one first</source>
        <translation>«&#xa0;Exporter le maillage&#xa0;» écrit une surface de maillage&#xa0;: choisissez-en d’abord une</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>impossible d’écrire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>Export Mesh</source>
        <translation>Exporter le maillage</translation>
    </message>
    <message>
        <source>Steps of %1 before every vertex is moved to its limit position:</source>
        <translation>Étapes de %1 avant que chaque sommet soit placé à sa position limite&#xa0;:</translation>
    </message>
    <message>
        <source>Wavefront OBJ (*.obj)</source>
        <translation>Wavefront OBJ (*.obj)</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Écrit&#xa0;: %1</translation>
    </message>
    <message>
        <source>Copy Matrices as &amp;MATLAB</source>
        <translation>Copier les matrices en MA&amp;TLAB</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n matrices as MATLAB cell arrays (for jsr() of the JSR toolbox).</source>
        <translation>
            <numerusform>%n matrice copiée en tableau de cellules MATLAB (pour jsr() de la JSR toolbox).</numerusform>
            <numerusform>%n matrices copiées en tableaux de cellules MATLAB (pour jsr() de la JSR toolbox).</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>Impor&amp;ter…</translation>
    </message>
    <message>
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <source>Export &amp;Item As…</source>
        <translation>Exporter l’é&amp;lément sous…</translation>
    </message>
    <message>
        <source>%1: no entry could be imported</source>
        <translation>%1&#xa0;: aucune entrée n’a pu être importée</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importer %1</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importer</translation>
    </message>
    <message>
        <source>Everything Attractor Workbench imports (*.ifs *.obj *.off *.ply);;Fractint IFS (*.ifs);;Meshes (*.obj *.off *.ply)</source>
        <translation type="vanished">Tout ce qu’Attractor Workbench sait importer (*.ifs *.obj *.off *.ply);;IFS Fractint (*.ifs);;Maillages (*.obj *.off *.ply)</translation>
    </message>
    <message>
        <source>Imported the other entries; these were left out:</source>
        <translation type="vanished">Les autres entrées ont été importées&#x202f;; celles-ci ont été laissées de côté&#xa0;:</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>Importé&#xa0;: %1</translation>
    </message>
    <message>
        <source>Export Item As writes an item with maps: choose one first</source>
        <translation>«&#xa0;Exporter l’élément sous&#xa0;» écrit un élément doté d’applications&#xa0;: choisissez-en d’abord un</translation>
    </message>
    <message>
        <source>%1 has no matrices to export</source>
        <translation>%1 n’a pas de matrices à exporter</translation>
    </message>
    <message>
        <source>%1: Export Item As writes .ifs (Fractint) or .m (MATLAB) files</source>
        <translation type="vanished">%1&#xa0;: «&#xa0;Exporter l’élément sous&#xa0;» écrit des fichiers .ifs (Fractint) ou .m (MATLAB)</translation>
    </message>
    <message>
        <source>Export Item As</source>
        <translation>Exporter l’élément sous</translation>
    </message>
    <message>
        <source>Fractint IFS (*.ifs);;MATLAB cell arrays of the matrices (*.m)</source>
        <translation type="vanished">IFS Fractint (*.ifs);;Matrices en tableaux de cellules MATLAB (*.m)</translation>
    </message>
    <message>
        <source>Everything Attractor Workbench imports (*.ifs *.flame *.flam3 *.obj *.off *.ply);;Fractint IFS (*.ifs);;Fractal flames: flam3, Apophysis, JWildfire (*.flame *.flam3);;Meshes (*.obj *.off *.ply)</source>
        <translation>Tout ce qu’Attractor Workbench importe (*.ifs *.flame *.flam3 *.obj *.off *.ply);;IFS Fractint (*.ifs);;Flammes fractales&#xa0;: flam3, Apophysis, JWildfire (*.flame *.flam3);;Maillages (*.obj *.off *.ply)</translation>
    </message>
    <message>
        <source>Imported the others; these were left out:</source>
        <translation>Les autres ont été importés&#xa0;; ceux-ci ont été laissés de côté&#xa0;:</translation>
    </message>
    <message>
        <source>Imported with these losses:</source>
        <translation>Importé avec ces pertes&#xa0;:</translation>
    </message>
    <message>
        <source>%1: Export Item As writes .ifs (Fractint), .flame (flam3) or .m (MATLAB) files</source>
        <translation>%1&#xa0;: «&#xa0;Exporter l’élément sous&#xa0;» écrit des fichiers .ifs (Fractint), .flame (flam3) ou .m (MATLAB)</translation>
    </message>
    <message>
        <source>Fractint IFS (*.ifs);;Fractal flame for flam3-render, Apophysis, JWildfire (*.flame);;MATLAB cell arrays of the matrices (*.m)</source>
        <translation>IFS Fractint (*.ifs);;Flamme fractale pour flam3-render, Apophysis, JWildfire (*.flame);;Tableaux de cellules MATLAB des matrices (*.m)</translation>
    </message>
    <message>
        <source>An .exr file holds the raw density of an attractor drawn in the plane: choose the Attractor view of such an item.</source>
        <translation>Un fichier .exr contient la densité brute d’un attracteur dessiné dans le plan&#xa0;: choisissez la vue Attracteur d’un tel élément.</translation>
    </message>
    <message>
        <source>Unknown format &quot;%1&quot;: use .png, .svg or .pdf (.tex for the matrices, .exr for the attractor&apos;s raw density).</source>
        <translation>Format «&#xa0;%1&#xa0;» inconnu&#xa0;: utilisez .png, .svg ou .pdf (.tex pour les matrices, .exr pour la densité brute de l’attracteur).</translation>
    </message>
    <message>
        <source>Projects and figures with their item (*.awb *.png *.svg);;Attractor Workbench projects (*.awb);;Exported figures (*.png *.svg);;Other tools&apos; IFS files, as a new project (*.ifs *.flame *.flam3);;All files (*)</source>
        <translation>Projets et figures avec leur élément (*.awb *.png *.svg);;Projets Attractor Workbench (*.awb);;Figures exportées (*.png *.svg);;Fichiers IFS d’autres outils, en nouveau projet (*.ifs *.flame *.flam3);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Outils</translation>
    </message>
    <message>
        <source>Python Console</source>
        <translation>Console Python</translation>
    </message>
    <message>
        <source>Save &amp;Recording…</source>
        <translation>Enregistrer l’&amp;enregistrement…</translation>
    </message>
    <message>
        <source>Save the edits since the project was opened as a Python script that replays them on the file</source>
        <translation>Enregistrer les modifications depuis l’ouverture du projet en un script Python qui les rejoue sur le fichier</translation>
    </message>
    <message>
        <source>&amp;Clear Recording</source>
        <translation>&amp;Effacer l’enregistrement</translation>
    </message>
    <message>
        <source>Start the recording again from the document as it is now</source>
        <translation>Recommencer l’enregistrement à partir du document tel qu’il est</translation>
    </message>
    <message>
        <source>Save Recording</source>
        <translation>Enregistrer l’enregistrement</translation>
    </message>
    <message>
        <source>Python scripts (*.py)</source>
        <translation>Scripts Python (*.py)</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n recorded edit(s) to %1</source>
        <translation>
            <numerusform>%n modification enregistrée dans %1</numerusform>
            <numerusform>%n modifications enregistrées dans %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Run Python &amp;Script…</source>
        <translation>Exécuter un &amp;script Python…</translation>
    </message>
    <message>
        <source>Run a Python script on the open document, in the Python console</source>
        <translation>Exécuter un script Python sur le document ouvert, dans la console Python</translation>
    </message>
    <message>
        <source>Run Python Script</source>
        <translation>Exécuter un script Python</translation>
    </message>
    <message>
        <source>&amp;Gallery…</source>
        <translation>&amp;Galerie…</translation>
    </message>
    <message>
        <source>The examples as thumbnails: the papers&apos; figures, meshes, masks</source>
        <translation>Les exemples sous forme de vignettes&#xa0;: figures des articles, maillages, masques</translation>
    </message>
    <message>
        <source>Exported the figure to %1</source>
        <translation>Figure exportée vers %1</translation>
    </message>
    <message>
        <source>000 Schaefer, Levin, Goldman: Subdivision Schemes and Attractors</source>
        <translation>000 Schaefer, Levin, Goldman&#xa0;: Schémas de subdivision et attracteurs</translation>
    </message>
    <message>
        <source>001 Li et al.: Normal Vector Based Subdivision</source>
        <translation>001 Li et al.&#xa0;: Subdivision fondée sur les vecteurs normaux</translation>
    </message>
    <message>
        <source>002 John: All Bézier Curves Are Attractors</source>
        <translation>002 John&#xa0;: Toutes les courbes de Bézier sont des attracteurs</translation>
    </message>
    <message>
        <source>003 BCIFS Junction Curves</source>
        <translation>003 Courbes de jonction BCIFS</translation>
    </message>
    <message>
        <source>004 Ptáčková: Fractals and Splines</source>
        <translation>004 Ptáčková&#xa0;: Fractales et splines</translation>
    </message>
    <message>
        <source>Meshes</source>
        <translation>Maillages</translation>
    </message>
    <message>
        <source>Masks, Animations and Other Tools&apos; Files</source>
        <translation>Masques, animations et fichiers d’autres outils</translation>
    </message>
    <message>
        <source>All %1 faces are triangles: Loop keeps them triangles (Catmull–Clark would make each one three quads around a new valence-3 vertex).

Subdivision scheme:</source>
        <translation>Les %1 faces sont toutes des triangles&#xa0;: Loop les conserve en triangles (Catmull–Clark ferait de chacune trois quadrilatères autour d’un nouveau sommet de valence 3).

Schéma de subdivision&#xa0;:</translation>
    </message>
    <message>
        <source>Regularity &amp;Atlas…</source>
        <translation>&amp;Atlas de régularité…</translation>
    </message>
    <message>
        <source>Where the selected curve&apos;s family of schemes is C^k, over one or two of its parameters (on a Dask cluster)</source>
        <translation>Où la famille de schémas de la courbe sélectionnée est C^k, selon un ou deux de ses paramètres (sur un cluster Dask)</translation>
    </message>
    <message>
        <source>Automaton</source>
        <translation>Automate</translation>
    </message>
    <message>
        <source>Edge %1–%2: sharpness %3 (Item &gt; Crease Edge… changes it)</source>
        <translation>Arête %1–%2 : netteté %3 (Élément &gt; Arête vive… la change)</translation>
    </message>
    <message>
        <source>&amp;Crease Edge…</source>
        <translation>&amp;Arête vive…</translation>
    </message>
    <message>
        <source>The sharpness of the mesh edge clicked in the 3D view</source>
        <translation>La netteté de l’arête du maillage cliquée dans la vue 3D</translation>
    </message>
    <message>
        <source>Sharpen &amp;Vertex…</source>
        <translation>Rendre le &amp;sommet vif…</translation>
    </message>
    <message>
        <source>The corner sharpness of the mesh vertex clicked in the 3D view</source>
        <translation>La netteté de coin du sommet du maillage cliqué dans la vue 3D</translation>
    </message>
    <message>
        <source>Sharp features belong to mesh surfaces: choose one first</source>
        <translation>Les éléments vifs appartiennent aux surfaces de maillage : choisissez-en une d’abord</translation>
    </message>
    <message>
        <source>Click an edge of the control mesh in the 3D view first</source>
        <translation>Cliquez d’abord sur une arête du maillage de contrôle dans la vue 3D</translation>
    </message>
    <message>
        <source>Click a vertex of the control mesh in the 3D view first</source>
        <translation>Cliquez d’abord sur un sommet du maillage de contrôle dans la vue 3D</translation>
    </message>
    <message>
        <source>Crease Edge</source>
        <translation>Arête vive</translation>
    </message>
    <message>
        <source>Sharpness of the edge from vertex %1 to vertex %2 (0: smooth; the crease rules for that many levels; 10: for ever):</source>
        <translation>Netteté de l’arête du sommet %1 au sommet %2 (0 : lisse ; les règles d’arête vive pendant autant de niveaux ; 10 : pour toujours) :</translation>
    </message>
    <message>
        <source>Sharpen Vertex</source>
        <translation>Rendre le sommet vif</translation>
    </message>
    <message>
        <source>Sharpness of vertex %1 (0: smooth; a corner for that many levels; 10: for ever):</source>
        <translation>Netteté du sommet %1 (0 : lisse ; un coin pendant autant de niveaux ; 10 : pour toujours) :</translation>
    </message>
    <message>
        <source>Not repaired: %1</source>
        <translation>Non réparé : %1</translation>
    </message>
    <message>
        <source>%1

Repair the mesh? These changes are well defined:

%2</source>
        <translation>%1

Réparer le maillage ? Ces modifications sont bien définies :

%2</translation>
    </message>
    <message>
        <source>Even repaired: %1</source>
        <translation>Même réparé : %1</translation>
    </message>
    <message>
        <source>Repaired: %1</source>
        <translation>Réparé : %1</translation>
    </message>
    <message>
        <source>Imported with these losses and changes:</source>
        <translation>Importé avec ces pertes et modifications :</translation>
    </message>
    <message>
        <source>The mesh is %1.

Repair it instead? These changes are well defined:

%2

No imports it as it is.</source>
        <translation>Le maillage est %1.

Le réparer plutôt ? Ces modifications sont bien définies :

%2

Non l’importe tel quel.</translation>
    </message>
    <message>
        <source>The mesh is %1.</source>
        <translation>Le maillage est %1.</translation>
    </message>
    <message>
        <source>Face %1: a hole (Item &gt; Toggle Hole fills it)</source>
        <translation>Face %1 : un trou (Élément &gt; Basculer le trou le remplit)</translation>
    </message>
    <message>
        <source>Face %1 (Item &gt; Toggle Hole makes it a hole)</source>
        <translation>Face %1 (Élément &gt; Basculer le trou en fait un trou)</translation>
    </message>
    <message>
        <source>Toggle &amp;Hole</source>
        <translation>Basculer le &amp;trou</translation>
    </message>
    <message>
        <source>Make the mesh face clicked in the 3D view a hole, or fill it</source>
        <translation>Fait de la face du maillage cliquée dans la vue 3D un trou, ou la remplit</translation>
    </message>
    <message>
        <source>Click inside a face of the control mesh in the 3D view first</source>
        <translation>Cliquez d’abord à l’intérieur d’une face du maillage de contrôle dans la vue 3D</translation>
    </message>
</context>
<context>
    <name>awb::MatrixHeatMap</name>
    <message>
        <source>%1 (%2, %3) = %4</source>
        <translation>%1 (%2, %3) = %4</translation>
    </message>
</context>
<context>
    <name>awb::MatrixView</name>
    <message>
        <source>%1 %2 %3i (modulus %4)</source>
        <translation>%1 %2 %3i (module %4)</translation>
    </message>
    <message>
        <source>Sum of row %1: %2</source>
        <translation>Somme de la ligne %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>Sum of column %1: %2</source>
        <translation>Somme de la colonne %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>“%1” is not a finite number: %2, row %3, column %4 was not changed.</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas un nombre fini&#xa0;: le coefficient de %2 en ligne %3, colonne %4 n’a pas été modifié.</translation>
    </message>
    <message>
        <source>A block</source>
        <translation>bloc A</translation>
    </message>
    <message>
        <source>b row</source>
        <translation>ligne b</translation>
    </message>
    <message>
        <source>fixed part of the lifted map</source>
        <translation>partie fixe de l’application relevée</translation>
    </message>
    <message>
        <source>— &lt;span style=&apos;background:#e2ecfa&apos;&gt;&amp;nbsp;A&amp;nbsp;&lt;/span&gt; block, &lt;span style=&apos;background:#fcecd6&apos;&gt;&amp;nbsp;b&amp;nbsp;&lt;/span&gt; row</source>
        <translation>— bloc &lt;span style=&apos;background:#e2ecfa&apos;&gt;&amp;nbsp;A&amp;nbsp;&lt;/span&gt;, ligne &lt;span style=&apos;background:#fcecd6&apos;&gt;&amp;nbsp;b&amp;nbsp;&lt;/span&gt;</translation>
    </message>
    <message>
        <source>(complex entries)</source>
        <translation>(coefficients complexes)</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Remove the map %1 from the IFS (one undo step)</source>
        <translation>Supprimer l&apos;application %1 de l&apos;IFS (une étape d&apos;annulation)</translation>
    </message>
    <message>
        <source>Add a Map</source>
        <translation>Ajouter une application</translation>
    </message>
    <message>
        <source>A new map S_(p+1), a copy of the last one to edit cell by cell (one undo step)</source>
        <translation>Une nouvelle application S_(p+1), copie de la dernière, à modifier cellule par cellule (une étape d&apos;annulation)</translation>
    </message>
</context>
<context>
    <name>awb::MeshInputs</name>
    <message>
        <source>%1 vertices; a mesh item takes at most %2</source>
        <translation>%1 sommets&#x202f;; un élément maillage en accepte au plus %2</translation>
    </message>
    <message>
        <source>%1 faces; a mesh item takes at most %2</source>
        <translation>%1 faces&#x202f;; un élément maillage en accepte au plus %2</translation>
    </message>
</context>
<context>
    <name>awb::Messages</name>
    <message>
        <source>… and %1 more lines: Show Details… lists them all.</source>
        <translation>… et %1 lignes de plus&#xa0;: «&#xa0;Montrer les détails…&#xa0;» les affiche toutes.</translation>
    </message>
    <message>
        <source>Show Details… shows the whole text.</source>
        <translation>«&#xa0;Montrer les détails…&#xa0;» affiche le texte complet.</translation>
    </message>
</context>
<context>
    <name>awb::MoveControlPointsCommand</name>
    <message numerus="yes">
        <source>Move %n control points of %1</source>
        <translation>
            <numerusform>Déplacer %n point de contrôle de %1</numerusform>
            <numerusform>Déplacer %n points de contrôle de %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Move a control point of %1</source>
        <translation>Déplacer un point de contrôle de %1</translation>
    </message>
</context>
<context>
    <name>awb::MoveItemCommand</name>
    <message>
        <source>Move %1</source>
        <translation>Déplacer %1</translation>
    </message>
</context>
<context>
    <name>awb::NormalVectorItem</name>
    <message>
        <source>Normal-vector curve</source>
        <translation>Courbe à vecteurs normaux</translation>
    </message>
    <message>
        <source>Change normal-vector scheme of %1</source>
        <translation>Modifier le schéma à vecteurs normaux de %1</translation>
    </message>
    <message>
        <source>the normal-vector scheme is not linear: it has no subdivision matrices (001 eq. (1))</source>
        <translation>le schéma à vecteurs normaux n’est pas linéaire&#xa0;: il n’a pas de matrices de subdivision (001 éq. (1))</translation>
    </message>
    <message>
        <source>No equivalent IFS: %1</source>
        <translation>Pas d’IFS équivalent&#xa0;: %1</translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation type="vanished">true ou false attendu</translation>
    </message>
    <message>
        <source>expected an array of sign rules</source>
        <translation>tableau de règles de signe attendu</translation>
    </message>
    <message>
        <source>expected one of &quot;%1&quot;</source>
        <translation>une valeur parmi &quot;%1&quot; attendue</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Own rules</source>
        <translation>Règles personnalisées</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Étapes</translation>
    </message>
    <message>
        <source>Subdivision steps of the polygon shown</source>
        <translation>Étapes de subdivision du polygone affiché</translation>
    </message>
    <message>
        <source>Normal direction</source>
        <translation>Sens de la normale</translation>
    </message>
    <message>
        <source>Counter-clockwise (positive)</source>
        <translation>Sens trigonométrique (positif)</translation>
    </message>
    <message>
        <source>Clockwise (negative)</source>
        <translation>Sens horaire (négatif)</translation>
    </message>
    <message>
        <source>Closed polygon</source>
        <translation>Polygone fermé</translation>
    </message>
    <message>
        <source>α%1</source>
        <translation>α%1</translation>
    </message>
    <message>
        <source>Rules</source>
        <translation>Règles</translation>
    </message>
    <message>
        <source>Position of new point %1 along the edge (001 eq. (1))</source>
        <translation type="vanished">Position du nouveau point %1 le long de l’arête (001 éq. (1))</translation>
    </message>
    <message>
        <source>β%1</source>
        <translation>β%1</translation>
    </message>
    <message>
        <source>Displacement of new point %1 along the normal</source>
        <translation type="vanished">Déplacement du nouveau point %1 le long de la normale</translation>
    </message>
    <message>
        <source>Signs of β</source>
        <translation>Signes de β</translation>
    </message>
    <message>
        <source>How the sign of β alternates: &quot;constant&quot;, &quot;edge-alternating&quot;, &quot;level-edge-alternating&quot; or &quot;level-alternating&quot;; none, one, or one per rule</source>
        <translation>Comment le signe de β alterne&#xa0;: &quot;constant&quot;, &quot;edge-alternating&quot;, &quot;level-edge-alternating&quot; ou &quot;level-alternating&quot;&#x202f;; aucun, un seul, ou un par règle</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Points de contrôle</translation>
    </message>
</context>
<context>
    <name>awb::NormalVectorSpec</name>
    <message>
        <source>unknown preset &quot;%1&quot;</source>
        <translation>préréglage «&#xa0;%1&#xa0;» inconnu</translation>
    </message>
    <message>
        <source>%1 steps: at least 0 and at most %2 are allowed</source>
        <translation>%1 étapes&#xa0;: le nombre doit être compris entre 0 et %2</translation>
    </message>
    <message>
        <source>need at least 2 rules (p &gt;= 2), got %1</source>
        <translation>il faut au moins 2 règles (p &gt;= 2) (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>%1 values of beta for %2 of alpha: need one per rule</source>
        <translation>%1 valeurs de bêta pour %2 valeurs d’alpha&#xa0;: il en faut une par règle</translation>
    </message>
    <message>
        <source>%1 signs for %2 rules: give none, one, or one per rule</source>
        <translation>%1 signes pour %2 règles&#xa0;: n’en donnez aucun, un seul, ou un par règle</translation>
    </message>
    <message>
        <source>%1_%2 is not a finite number</source>
        <translation>%1_%2 n’est pas un nombre fini</translation>
    </message>
</context>
<context>
    <name>awb::PaletteDialog</name>
    <message>
        <source>Map Colours</source>
        <translation>Couleurs des applications</translation>
    </message>
    <message>
        <source>The colour of the points each map f&lt;sub&gt;i&lt;/sub&gt; makes (Style: colour by map or by address).</source>
        <translation>La couleur des points produits par chaque application f&lt;sub&gt;i&lt;/sub&gt; (Style&#xa0;: couleur par application ou par adresse).</translation>
    </message>
    <message>
        <source>Colour of map %1</source>
        <translation>Couleur de l’application %1</translation>
    </message>
    <message>
        <source>Map %1:</source>
        <translation>Application %1&#xa0;:</translation>
    </message>
    <message>
        <source>Use the &amp;Default Colours</source>
        <translation>Utiliser les couleurs par &amp;défaut</translation>
    </message>
</context>
<context>
    <name>awb::PointExport</name>
    <message>
        <source>cannot write the points: %1</source>
        <translation>impossible d’écrire les points&#xa0;: %1</translation>
    </message>
    <message>
        <source>--address needs an item drawn by one IFS; this one is drawn by an automaton</source>
        <translation>--address demande un élément tracé par un seul IFS&#x202f;; celui-ci est tracé par un automate</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is drawn by an automaton: PLY export covers items with one IFS</source>
        <translation>«&#xa0;%1&#xa0;» est tracé par un automate&#xa0;: l’export PLY ne concerne que les éléments à un seul IFS</translation>
    </message>
    <message>
        <source>wrote %1 points, expected %2</source>
        <translation>%1 points écrits, %2 attendus</translation>
    </message>
    <message>
        <source>this item is a fractal flame: its points come from its own chaos game, not from iterating maps (render its picture instead)</source>
        <translation>cet élément est une flamme fractale : ses points proviennent de son propre jeu du chaos, et non de l&apos;itération d&apos;applications (faites plutôt le rendu de son image)</translation>
    </message>
</context>
<context>
    <name>awb::PointExportDialog</name>
    <message>
        <source>Export Points of %1</source>
        <translation>Exporter les points de %1</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Parcourir…</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Fichier&#xa0;:</translation>
    </message>
    <message>
        <source>CSV text: x, y[, z], map, view</source>
        <translation>Texte CSV&#xa0;: x, y[, z], application, vue</translation>
    </message>
    <message>
        <source>PLY point cloud: x, y, z, map colour, map</source>
        <translation>Nuage de points PLY&#xa0;: x, y, z, couleur de l’application, application</translation>
    </message>
    <message>
        <source>F&amp;ormat:</source>
        <translation>F&amp;ormat&#xa0;:</translation>
    </message>
    <message>
        <source>The points of F^k(X0): every image of the start set&apos;s vertices after k steps of the Hutchinson operator</source>
        <translation>Les points de F^k(X0)&#xa0;: toutes les images des sommets de l’ensemble initial après k itérations de l’opérateur de Hutchinson</translation>
    </message>
    <message>
        <source>&amp;Depth k:</source>
        <translation>Pro&amp;fondeur k&#xa0;:</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exporter</translation>
    </message>
    <message>
        <source>Export Points</source>
        <translation>Exporter les points</translation>
    </message>
    <message>
        <source>CSV text (*.csv);;PLY point cloud (*.ply)</source>
        <translation>Texte CSV (*.csv);;Nuage de points PLY (*.ply)</translation>
    </message>
    <message>
        <source>The number of points depends on the automaton.</source>
        <translation>Le nombre de points dépend de l’automate.</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>%1 points</translation>
    </message>
    <message>
        <source> — too many (at most %1): choose a smaller depth.</source>
        <translation> — trop nombreux (au plus %1)&#xa0;: choisissez une profondeur plus petite.</translation>
    </message>
    <message>
        <source>%1 cannot be computed: %2</source>
        <translation>%1 ne peut pas être calculé&#xa0;: %2</translation>
    </message>
    <message>
        <source>Start set: %1</source>
        <translation>Ensemble initial&#xa0;: %1</translation>
    </message>
    <message>
        <source>Depth %1 gives %2 points, more than %3: choose a smaller depth.</source>
        <translation>La profondeur %1 donne %2 points, soit plus de %3&#xa0;: choisissez une profondeur plus petite.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Impossible d’écrire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>Writing the points of %1…</source>
        <translation>Écriture des points de %1…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Exporting the points was cancelled; nothing was written.</source>
        <translation>L’exportation des points a été annulée&#x202f;; rien n’a été écrit.</translation>
    </message>
</context>
<context>
    <name>awb::PreferencesDialog</name>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
</context>
<context>
    <name>awb::Project</name>
    <message>
        <source>Item</source>
        <translation>Élément</translation>
    </message>
    <message>
        <source>the name cannot be empty</source>
        <translation>le nom ne peut pas être vide</translation>
    </message>
    <message>
        <source>another item is already called &quot;%1&quot;</source>
        <translation>un autre élément s’appelle déjà «&#xa0;%1&#xa0;»</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n items</source>
        <translation>
            <numerusform>Supprimer %n élément</numerusform>
            <numerusform>Supprimer %n éléments</numerusform>
        </translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>Renommer %1 en %2</translation>
    </message>
    <message>
        <source>the project has no file name yet: use &quot;Save As&quot;</source>
        <translation>le projet n’a pas encore de nom de fichier&#xa0;: utilisez «&#xa0;Enregistrer sous&#xa0;»</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
</context>
<context>
    <name>awb::ProjectIO</name>
    <message>
        <source>%1: cannot save: %2</source>
        <translation>%1&#xa0;: impossible d’enregistrer&#xa0;: %2</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1&#xa0;: impossible d’ouvrir&#xa0;: %2</translation>
    </message>
    <message>
        <source>%1: the file is %2 MB; project files larger than %3 MB are refused (a project is at most a few MB)</source>
        <translation>%1&#xa0;: le fichier fait %2 Mo&#x202f;; les fichiers de projet de plus de %3 Mo sont refusés (un projet fait au plus quelques Mo)</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1&#xa0;: impossible de lire&#xa0;: %2</translation>
    </message>
    <message>
        <source>%1: the file is empty</source>
        <translation>%1&#xa0;: le fichier est vide</translation>
    </message>
    <message>
        <source>%1: the file holds only white space</source>
        <translation>%1&#xa0;: le fichier ne contient que des blancs</translation>
    </message>
    <message>
        <source>%1: the file is UTF-16 or UTF-32 text; project files are UTF-8 (save it again as UTF-8)</source>
        <translation>%1&#xa0;: le fichier est un texte UTF-16 ou UTF-32&#x202f;; les fichiers de projet sont en UTF-8 (enregistrez-le de nouveau en UTF-8)</translation>
    </message>
    <message>
        <source>%1: expected a JSON object at the top level</source>
        <translation>%1&#xa0;: objet JSON attendu au premier niveau</translation>
    </message>
    <message>
        <source>%1: not valid JSON: %2 at line %3, column %4</source>
        <translation>%1&#xa0;: JSON non valide&#xa0;: %2 à la ligne %3, colonne %4</translation>
    </message>
    <message>
        <source>expected &quot;%1&quot;: this is not an Attractor Workbench project</source>
        <translation>&quot;%1&quot; attendu&#xa0;: ce n’est pas un projet Attractor Workbench</translation>
    </message>
    <message>
        <source>%1: the file has format version %2, written by a newer version of Attractor Workbench; this version reads format version %3 only. Please update the application.</source>
        <translation>%1&#xa0;: le fichier est au format version %2, écrit par une version plus récente d’Attractor Workbench&#x202f;; cette version ne lit que le format version %3. Veuillez mettre à jour l’application.</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>manquant</translation>
    </message>
    <message>
        <source>expected an array</source>
        <translation>tableau attendu</translation>
    </message>
    <message>
        <source>%1: field &quot;%2&quot;: %3</source>
        <translation>%1&#xa0;: champ &quot;%2&quot;&#xa0;: %3</translation>
    </message>
    <message>
        <source>item %1</source>
        <translation>élément %1</translation>
    </message>
    <message>
        <source>%1: %2: field &quot;%3&quot;: %4</source>
        <translation>%1&#xa0;: %2&#xa0;: champ &quot;%3&quot;&#xa0;: %4</translation>
    </message>
    <message>
        <source>field &quot;%1&quot;: %2</source>
        <translation>champ &quot;%1&quot;&#xa0;: %2</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>objet attendu</translation>
    </message>
    <message>
        <source>unknown item type %1; this version knows %2</source>
        <translation>type d’élément %1 inconnu&#x202f;; cette version connaît %2</translation>
    </message>
    <message>
        <source>another item is already called %1</source>
        <translation>un autre élément s’appelle déjà %1</translation>
    </message>
    <message>
        <source>expected an array of items</source>
        <translation>tableau d’éléments attendu</translation>
    </message>
    <message>
        <source>expected an array of lifted points [x, y, c1, ...]</source>
        <translation>tableau de points relevés [x, y, c1, ...] attendu</translation>
    </message>
    <message>
        <source>expected a lifted point [x, y, c1, ...]</source>
        <translation>point relevé [x, y, c1, ...] attendu</translation>
    </message>
    <message>
        <source>expected an array of &quot;#rrggbb&quot; strings</source>
        <translation type="vanished">tableau de chaînes &quot;#rrggbb&quot; attendu</translation>
    </message>
    <message>
        <source>expected a string &quot;#rrggbb&quot;</source>
        <translation type="vanished">chaîne &quot;#rrggbb&quot; attendue</translation>
    </message>
    <message>
        <source>a &quot;vertex-limits&quot; start set has no points (it starts at the limit positions of the mesh&apos;s vertices)</source>
        <translation>un ensemble initial &quot;vertex-limits&quot; n’a pas de points (il part des positions limites des sommets du maillage)</translation>
    </message>
    <message>
        <source>the item</source>
        <translation>l’élément</translation>
    </message>
    <message>
        <source>expected an array of net point indices [0, 9, 18]</source>
        <translation>tableau d’indices de points du réseau attendu [0, 9, 18]</translation>
    </message>
    <message>
        <source>%1 net point indices; a start set takes at most %2</source>
        <translation>%1 indices de points du réseau ; un ensemble initial en prend au plus %2</translation>
    </message>
    <message>
        <source>expected a net point index (an integer from 0)</source>
        <translation>indice de point du réseau attendu (un entier à partir de 0)</translation>
    </message>
</context>
<context>
    <name>awb::ProjectTreeModel</name>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message numerus="yes">
        <source>Move %n items</source>
        <translation>
            <numerusform>Déplacer %n élément</numerusform>
            <numerusform>Déplacer %n éléments</numerusform>
        </translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Déplacer %1</translation>
    </message>
</context>
<context>
    <name>awb::PropertiesWidget</name>
    <message>
        <source>Value refused</source>
        <translation>Valeur refusée</translation>
    </message>
    <message>
        <source>%1 cannot be set to %2.</source>
        <translation>%1 ne peut pas prendre la valeur %2.</translation>
    </message>
    <message>
        <source>No item selected.</source>
        <translation>Aucun élément sélectionné.</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="vanished">&amp;Nom&#xa0;:</translation>
    </message>
    <message>
        <source>The name is empty or already taken.</source>
        <translation type="vanished">Le nom est vide ou déjà utilisé.</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Paramètres</translation>
    </message>
    <message>
        <source>Re </source>
        <translation>Re </translation>
    </message>
    <message>
        <source>Im </source>
        <translation>Im </translation>
    </message>
    <message>
        <source>Start set X0</source>
        <translation type="vanished">Ensemble initial X0</translation>
    </message>
    <message>
        <source>Point</source>
        <translation type="vanished">Point</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation type="vanished">Segment</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation type="vanished">Triangle</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation type="vanished">Polygone</translation>
    </message>
    <message>
        <source>Points</source>
        <translation type="vanished">Points</translation>
    </message>
    <message>
        <source>Lifted points</source>
        <translation type="vanished">Points relevés</translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation type="vanished">Type&#xa0;:</translation>
    </message>
    <message>
        <source>Drag its vertices in the attractor view.</source>
        <translation type="vanished">Faites glisser ses sommets dans la vue de l’attracteur.</translation>
    </message>
    <message>
        <source>Points of the lifted space of 000 §2: x, y, then the extra coordinates of the lifting, the homogeneous 1 implied. Commas between coordinates, &apos;;&apos; between points.</source>
        <translation type="vanished">Points de l’espace relevé de 000 §2&#xa0;: x, y, puis les coordonnées supplémentaires du relèvement, le 1 homogène étant implicite. Des virgules entre les coordonnées, «&#x202f;;&#xa0;» entre les points.</translation>
    </message>
    <message>
        <source>Lifted:</source>
        <translation type="vanished">Relevés&#xa0;:</translation>
    </message>
    <message>
        <source>The start set was refused.</source>
        <translation type="vanished">L’ensemble initial a été refusé.</translation>
    </message>
    <message>
        <source>The item has no control points.</source>
        <translation type="vanished">L’élément n’a pas de points de contrôle.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number.</source>
        <translation type="vanished">«&#xa0;%1&#xa0;» n’est pas un nombre.</translation>
    </message>
    <message>
        <source>Algorithm</source>
        <translation type="vanished">Algorithme</translation>
    </message>
    <message>
        <source>Deterministic</source>
        <translation type="vanished">Déterministe</translation>
    </message>
    <message>
        <source>Random (chaos game)</source>
        <translation type="vanished">Aléatoire (jeu du chaos)</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation type="vanished">Mode&#xa0;:</translation>
    </message>
    <message>
        <source>Depth:</source>
        <translation type="vanished">Profondeur&#xa0;:</translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation type="vanished">Échantillons&#xa0;:</translation>
    </message>
    <message>
        <source>Style</source>
        <translation type="vanished">Style</translation>
    </message>
    <message>
        <source>By map</source>
        <translation type="vanished">Par application</translation>
    </message>
    <message>
        <source>By address prefix</source>
        <translation type="vanished">Par préfixe d’adresse</translation>
    </message>
    <message>
        <source>Single colour</source>
        <translation type="vanished">Couleur unique</translation>
    </message>
    <message>
        <source>Colour:</source>
        <translation type="vanished">Couleur&#xa0;:</translation>
    </message>
    <message>
        <source>Prefix length:</source>
        <translation type="vanished">Longueur du préfixe&#xa0;:</translation>
    </message>
    <message>
        <source>Point size:</source>
        <translation type="vanished">Taille des points&#xa0;:</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Points de contrôle</translation>
    </message>
    <message>
        <source>Set %1 (%2)</source>
        <translation>Ensemble %1 (%2)</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a finite number.</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas un nombre fini.</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>Append a point after the last one</source>
        <translation>Ajouter un point après le dernier</translation>
    </message>
    <message>
        <source>Insert</source>
        <translation>Insérer</translation>
    </message>
    <message>
        <source>Insert a point before the selected one (halfway to its predecessor)</source>
        <translation>Insérer un point avant le point sélectionné (à mi-chemin de son prédécesseur)</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Delete the selected points (one undo step)</source>
        <translation>Supprimer les points sélectionnés (en une seule étape d’annulation)</translation>
    </message>
    <message>
        <source>The colour of each map&apos;s points: click to choose</source>
        <translation>La couleur des points de chaque application&#xa0;: cliquez pour la choisir</translation>
    </message>
    <message>
        <source>Default…</source>
        <translation>Par défaut…</translation>
    </message>
    <message>
        <source>Own…</source>
        <translation>Personnalisées…</translation>
    </message>
    <message>
        <source>Map colours:</source>
        <translation>Couleurs des applications&#xa0;:</translation>
    </message>
    <message>
        <source>Eigenvalues</source>
        <translation type="vanished">Valeurs propres</translation>
    </message>
    <message>
        <source>The item whose matrices are analysed</source>
        <translation type="vanished">L’élément dont les matrices sont analysées</translation>
    </message>
    <message>
        <source>S_i: the subdivision matrices (their eigenvalue 1 is affine invariance); A_i: the linear parts of the lifted maps, whose subdominant eigenvalue decides the tangents; M_i: the lifted maps themselves (003 §4, 004 §2.1)</source>
        <translation type="vanished">S_i&#xa0;: les matrices de subdivision (leur valeur propre 1 traduit l’invariance affine)&#x202f;; A_i&#xa0;: les parties linéaires des applications relevées, dont la valeur propre sous-dominante détermine les tangentes&#x202f;; M_i&#xa0;: les applications relevées elles-mêmes (003 §4, 004 §2.1)</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation type="vanished">Source&#xa0;:</translation>
    </message>
    <message>
        <source>Matrices:</source>
        <translation type="vanished">Matrices&#xa0;:</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="vanished">(aucun)</translation>
    </message>
    <message>
        <source>%1 (missing)</source>
        <translation type="vanished">%1 (manquant)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation type="vanished">Profondeur</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation type="vanished">Échantillons</translation>
    </message>
    <message>
        <source>Prefix length</source>
        <translation type="vanished">Longueur du préfixe</translation>
    </message>
    <message>
        <source>Point size</source>
        <translation type="vanished">Taille des points</translation>
    </message>
    <message>
        <source>%1 matrices %2_i, %3 eigenvalues, plotted in the centre; click an eigenvalue to mark its map (its matrices in the Matrices dock).</source>
        <translation>%1 matrices %2_i, %3 valeurs propres, tracées au centre ; cliquez sur une valeur propre pour marquer son application (ses matrices dans le panneau Matrices).</translation>
    </message>
    <message>
        <source>Vertex limits</source>
        <translation type="vanished">Positions limites des sommets</translation>
    </message>
    <message>
        <source>Vertex limits: the exact limit positions of the mesh&apos;s vertices, where its IFS with condensation starts. Drag the control points in the 3D view; click a purple diamond to analyse that extraordinary vertex.</source>
        <translation type="vanished">Positions limites des sommets&#xa0;: les positions limites exactes des sommets du maillage, d’où part son IFS avec condensation. Faites glisser les points de contrôle dans la vue 3D&#x202f;; cliquez sur un losange violet pour analyser ce sommet extraordinaire.</translation>
    </message>
    <message>
        <source>For a mesh surface: the extraordinary vertex whose local subdivision matrix is analysed</source>
        <translation type="vanished">Pour une surface de maillage&#xa0;: le sommet extraordinaire dont la matrice de subdivision locale est analysée</translation>
    </message>
    <message>
        <source>Vertex:</source>
        <translation type="vanished">Sommet&#xa0;:</translation>
    </message>
    <message>
        <source>(the mesh&apos;s matrices)</source>
        <translation type="vanished">(les matrices du maillage)</translation>
    </message>
    <message>
        <source>vertex %1 (n = %2)</source>
        <translation type="vanished">sommet %1 (n = %2)</translation>
    </message>
    <message>
        <source>centre of face %1 (n = %2)</source>
        <translation type="vanished">centre de la face %1 (n = %2)</translation>
    </message>
    <message>
        <source>centre of face %1 (missing)</source>
        <translation type="vanished">centre de la face %1 (manquant)</translation>
    </message>
    <message>
        <source>vertex %1 (missing)</source>
        <translation type="vanished">sommet %1 (manquant)</translation>
    </message>
    <message>
        <source>Xforms</source>
        <translation>Xforms</translation>
    </message>
</context>
<context>
    <name>awb::PythonConsole</name>
    <message>
        <source>Python: project, item, awb (attractor_workbench) and np</source>
        <translation>Python&#xa0;: project, item, awb (attractor_workbench) et np</translation>
    </message>
    <message>
        <source># Python %1 console: `project` is the open document, `item` the current item, `awb` the attractor_workbench module (help(awb)). Edits are undoable; every edit made in the window is shown below as the line that makes it (Tools &gt; Save Recording).</source>
        <translation># Console Python %1&#xa0;: `project` est le document ouvert, `item` l’élément courant, `awb` le module attractor_workbench (help(awb)). Les modifications peuvent être annulées&#xa0;; chaque modification faite dans la fenêtre s’affiche ci-dessous comme la ligne qui la fait (Outils &gt; Enregistrer l’enregistrement).</translation>
    </message>
    <message>
        <source># The recording starts again, from a new project.</source>
        <translation># L’enregistrement recommence, à partir d’un nouveau projet.</translation>
    </message>
    <message>
        <source># The recording starts again, from %1.</source>
        <translation># L’enregistrement recommence, à partir de %1.</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>impossible de lire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source># Running %1</source>
        <translation># Exécution de %1</translation>
    </message>
</context>
<context>
    <name>awb::Recovery</name>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1&#xa0;: impossible d’ouvrir&#xa0;: %2</translation>
    </message>
    <message>
        <source>%1: not an Attractor Workbench recovery file</source>
        <translation>%1&#xa0;: ce n’est pas un fichier de récupération d’Attractor Workbench</translation>
    </message>
    <message>
        <source>%1: written by a newer version of Attractor Workbench</source>
        <translation>%1&#xa0;: écrit par une version plus récente d’Attractor Workbench</translation>
    </message>
    <message>
        <source>%1: field &quot;project&quot;: expected an object</source>
        <translation>%1&#xa0;: champ &quot;project&quot;&#xa0;: objet attendu</translation>
    </message>
</context>
<context>
    <name>awb::RegularityAtlasWindow</name>
    <message>
        <source>Regularity Atlas</source>
        <translation>Atlas de régularité</translation>
    </message>
    <message>
        <source>Item:</source>
        <translation>Élément :</translation>
    </message>
    <message>
        <source>The mask with the parameters written into it, e.g. &quot;v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v&quot; (the six-point family).</source>
        <translation>Le masque avec les paramètres écrits dedans, p. ex. « v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v » (la famille à six points).</translation>
    </message>
    <message>
        <source>&amp;Mask:</source>
        <translation>&amp;Masque :</translation>
    </message>
    <message>
        <source>The parameter&apos;s name: omega, a, b, or a name in the mask.</source>
        <translation>Le nom du paramètre : omega, a, b, ou un nom figurant dans le masque.</translation>
    </message>
    <message>
        <source>Grid values, both ends included.</source>
        <translation>Valeurs de la grille, bornes incluses.</translation>
    </message>
    <message>
        <source>from</source>
        <translation>de</translation>
    </message>
    <message>
        <source>to</source>
        <translation>à</translation>
    </message>
    <message>
        <source>values</source>
        <translation>valeurs</translation>
    </message>
    <message>
        <source>&amp;Second parameter:</source>
        <translation>&amp;Second paramètre :</translation>
    </message>
    <message>
        <source>&amp;Parameter:</source>
        <translation>&amp;Paramètre :</translation>
    </message>
    <message>
        <source>The class the atlas refines around: its C^k boundaries.</source>
        <translation>La classe autour de laquelle l&apos;atlas affine : ses frontières C^k.</translation>
    </message>
    <message>
        <source>One parameter: each boundary&apos;s bracket narrows to this width.</source>
        <translation>Un paramètre : l&apos;intervalle encadrant chaque frontière se resserre jusqu&apos;à cette largeur.</translation>
    </message>
    <message>
        <source>Two parameters: how many times a cell whose corners disagree is split.</source>
        <translation>Deux paramètres : nombre de fois qu&apos;une cellule dont les coins ne concordent pas est subdivisée.</translation>
    </message>
    <message>
        <source>Class:</source>
        <translation>Classe :</translation>
    </message>
    <message>
        <source>Tolerance:</source>
        <translation>Tolérance :</translation>
    </message>
    <message>
        <source>Refinement levels:</source>
        <translation>Niveaux de raffinement :</translation>
    </message>
    <message>
        <source>Atlas:</source>
        <translation>Atlas :</translation>
    </message>
    <message numerus="yes">
        <source>A local Dask cluster (%n worker(s))</source>
        <translation>
            <numerusform>Un cluster Dask local (%n processus de calcul)</numerusform>
            <numerusform>Un cluster Dask local (%n processus de calcul)</numerusform>
        </translation>
    </message>
    <message>
        <source>The Dask scheduler named in Preferences (none set)</source>
        <translation>L&apos;ordonnanceur Dask indiqué dans les Préférences (aucun défini)</translation>
    </message>
    <message>
        <source>The Dask scheduler at %1</source>
        <translation>L&apos;ordonnanceur Dask à %1</translation>
    </message>
    <message>
        <source>This machine, one process (no Dask)</source>
        <translation>Cette machine, un seul processus (sans Dask)</translation>
    </message>
    <message>
        <source>&amp;Run on:</source>
        <translation>&amp;Exécuter sur :</translation>
    </message>
    <message>
        <source>&amp;Compute</source>
        <translation>&amp;Calculer</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>(none: select a subdivision curve)</source>
        <translation>(aucune : sélectionnez une courbe de subdivision)</translation>
    </message>
    <message>
        <source>Write the parameters&apos; names into the mask (&quot;v, 0, w, 0, 1/2 - w - v, 1, …&quot;), give their ranges, and Compute.</source>
        <translation>Écrivez les noms des paramètres dans le masque (« v, 0, w, 0, 1/2 - w - v, 1, … »), indiquez leurs plages, puis cliquez sur Calculer.</translation>
    </message>
    <message>
        <source>Give the parameters&apos; ranges and Compute: each point is a certified joint spectral radius, computed by python3 -m attractor_workbench.atlas.</source>
        <translation>Indiquez les plages des paramètres et cliquez sur Calculer : chaque point est un rayon spectral joint certifié, calculé par python3 -m attractor_workbench.atlas.</translation>
    </message>
    <message>
        <source>Select a subdivision curve first: the atlas moves its scheme&apos;s parameters.</source>
        <translation>Sélectionnez d&apos;abord une courbe de subdivision : l&apos;atlas fait varier les paramètres de son schéma.</translation>
    </message>
    <message>
        <source>No Dask scheduler is set: name one in Edit &gt; Preferences, or run on a local cluster.</source>
        <translation>Aucun ordonnanceur Dask n&apos;est défini : indiquez-en un dans Édition &gt; Préférences, ou exécutez sur un cluster local.</translation>
    </message>
    <message>
        <source>Could not write the project for the atlas: %1</source>
        <translation>Impossible d&apos;écrire le projet pour l&apos;atlas : %1</translation>
    </message>
    <message>
        <source>Computing in one process…</source>
        <translation>Calcul dans un seul processus…</translation>
    </message>
    <message>
        <source>Starting the Dask cluster…</source>
        <translation>Démarrage du cluster Dask…</translation>
    </message>
    <message>
        <source>Cancelling: the cluster&apos;s tasks are being cancelled…</source>
        <translation>Annulation : les tâches du cluster sont en cours d&apos;annulation…</translation>
    </message>
    <message>
        <source>Round 1: the grid&apos;s %1 points…</source>
        <translation>Tour 1 : les %1 points de la grille…</translation>
    </message>
    <message>
        <source>Round %1: %2 points where the class changes…</source>
        <translation>Tour %1 : %2 points où la classe change…</translation>
    </message>
    <message>
        <source>Round %1: %2 of %3 points; %4 in all, %5 s</source>
        <translation>Tour %1 : %2 points sur %3 ; %4 au total, %5 s</translation>
    </message>
    <message>
        <source>from %1 to %2</source>
        <translation>de %1 à %2</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s) in %1 round(s), %2 s on %3 worker(s) (%4).</source>
        <translation>
            <numerusform>%n point en %1 tour(s), %2 s sur %3 processus de calcul (%4).</numerusform>
            <numerusform>%n points en %1 tour(s), %2 s sur %3 processus de calcul (%4).</numerusform>
        </translation>
    </message>
    <message>
        <source>Nowhere certified C^%1.</source>
        <translation>Nulle part certifié C^%1.</translation>
    </message>
    <message>
        <source>C^%1 %2.</source>
        <translation>C^%1 %2.</translation>
    </message>
    <message>
        <source>The atlas gave no rows.</source>
        <translation>L&apos;atlas n&apos;a renvoyé aucune ligne.</translation>
    </message>
    <message>
        <source>Cancelled; the points computed so far are shown.</source>
        <translation>Annulé ; les points calculés jusqu&apos;ici sont affichés.</translation>
    </message>
    <message>
        <source>could not start %1: %2</source>
        <translation>impossible de démarrer %1 : %2</translation>
    </message>
    <message>
        <source>exit code %1</source>
        <translation>code de sortie %1</translation>
    </message>
    <message>
        <source>The atlas failed: %1</source>
        <translation>L&apos;atlas a échoué : %1</translation>
    </message>
    <message>
        <source>Add an item with %1</source>
        <translation>Ajouter un élément avec %1</translation>
    </message>
    <message>
        <source>Added &quot;%1&quot; (Edit &gt; Undo removes it).</source>
        <translation>« %1 » ajouté (Édition &gt; Annuler le retire).</translation>
    </message>
    <message>
        <source>the scheme refuses these parameters</source>
        <translation>le schéma refuse ces paramètres</translation>
    </message>
    <message>
        <source>No item added: %1</source>
        <translation>Aucun élément ajouté : %1</translation>
    </message>
</context>
<context>
    <name>awb::RegularityCertificate</name>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1 is not an index</source>
        <translation>%1 n&apos;est pas un indice</translation>
    </message>
    <message>
        <source>%1 has no array &quot;%2&quot;</source>
        <translation>%1 n&apos;a pas de tableau &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1 is not an array of numbers</source>
        <translation>%1 n&apos;est pas un tableau de nombres</translation>
    </message>
    <message>
        <source>&quot;polytope&quot; is not an awb-invariant-polytope object</source>
        <translation>&quot;polytope&quot; n&apos;est pas un objet awb-invariant-polytope</translation>
    </message>
    <message>
        <source>polytope.matrices[%1] is not square</source>
        <translation>polytope.matrices[%1] n&apos;est pas carrée</translation>
    </message>
    <message>
        <source>polytope.lambda[%1] holds a term that is not [index, coefficient]</source>
        <translation>polytope.lambda[%1] contient un terme qui n&apos;est pas de la forme [indice, coefficient]</translation>
    </message>
    <message>
        <source>the regularity is not exact: no invariant polytope closed, so there is no certificate (%1)</source>
        <translation>la régularité n&apos;est pas exacte&#xa0;: aucun polytope invariant ne s&apos;est fermé, il n&apos;y a donc pas de certificat (%1)</translation>
    </message>
    <message>
        <source>not JSON: %1 at offset %2</source>
        <translation>pas du JSON&#xa0;: %1 à la position %2</translation>
    </message>
    <message>
        <source>not an attractor-workbench regularity certificate (format %1, version 1)</source>
        <translation>pas un certificat de régularité attractor-workbench (format %1, version 1)</translation>
    </message>
    <message>
        <source>the scheme has no difference scheme to certify: %1</source>
        <translation>le schéma n&apos;a pas de schéma aux différences à certifier&#xa0;: %1</translation>
    </message>
    <message>
        <source>the certificate has %1 matrices, the scheme&apos;s analysis %2</source>
        <translation>le certificat a %1 matrices, l&apos;analyse du schéma %2</translation>
    </message>
    <message>
        <source>matrix %1 of the certificate is not the scheme&apos;s (the transition matrix T_%2 of its difference scheme)</source>
        <translation>la matrice %1 du certificat n&apos;est pas celle du schéma (la matrice de transition T_%2 de son schéma aux différences)</translation>
    </message>
    <message>
        <source>arity %1 and shift %2 do not match the scheme&apos;s (%3 and %4)</source>
        <translation>l&apos;arité %1 et le décalage %2 ne correspondent pas à ceux du schéma (%3 et %4)</translation>
    </message>
    <message>
        <source>the claimed Hölder exponent [%1, %2] is not what the polytope proves: [%3, %4]</source>
        <translation>l&apos;exposant de Hölder annoncé [%1, %2] n&apos;est pas celui que prouve le polytope&#xa0;: [%3, %4]</translation>
    </message>
    <message>
        <source>certificate verified: the Hölder exponent of the %1 lies in [%2, %3]; JSR in [%4, %5]</source>
        <translation>certificat vérifié&#xa0;: l&apos;exposant de Hölder du %1 est dans [%2, %3]&#xa0;; JSR dans [%4, %5]</translation>
    </message>
    <message>
        <source>certificate rejected: %1</source>
        <translation>certificat rejeté&#xa0;: %1</translation>
    </message>
</context>
<context>
    <name>awb::RegularityChart</name>
    <message>
        <source>Regularity of the four-point scheme</source>
        <translation>Régularité du schéma à quatre points</translation>
    </message>
    <message>
        <source>Certified Hölder regularity r(ω) of the four-point scheme</source>
        <translation>Régularité höldérienne certifiée r(ω) du schéma à quatre points</translation>
    </message>
    <message>
        <source>lower bound</source>
        <translation>borne inférieure</translation>
    </message>
    <message>
        <source>upper bound</source>
        <translation>borne supérieure</translation>
    </message>
    <message>
        <source>known: ω = 0 → 1, ω = 1/16 → 2</source>
        <translation type="vanished">connu&#xa0;: ω = 0 → 1, ω = 1/16 → 2</translation>
    </message>
    <message>
        <source>tension ω</source>
        <translation>tension ω</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Computing %1 values of ω…</source>
        <translation>Calcul pour %1 valeurs de ω…</translation>
    </message>
    <message>
        <source>%1 values of ω; widest interval %2 (bounds certified; the upper bound is exact for this interpolatory scheme)</source>
        <translation type="vanished">%1 valeurs de ω&#x202f;; intervalle le plus large&#xa0;: %2 (bornes certifiées&#x202f;; la borne supérieure est exacte pour ce schéma interpolant)</translation>
    </message>
    <message>
        <source>regularity r</source>
        <translation>régularité r</translation>
    </message>
    <message>
        <source>r(0) = 1, r(1/16) = 2</source>
        <translation>r(0) = 1, r(1/16) = 2</translation>
    </message>
    <message>
        <source>C%1 (certified)</source>
        <translation>C%1 (certifié)</translation>
    </message>
    <message>
        <source>; C¹ for ω in (%1, %2), the ends in [%3, %4] and [%5, %6]</source>
        <translation>&#xa0;; C¹ pour ω dans (%1, %2), les extrémités dans [%3, %4] et [%5, %6]</translation>
    </message>
    <message>
        <source>%1 values of ω; widest interval %2 (bounds certified; the upper bound is exact for this interpolatory scheme)%3</source>
        <translation>%1 valeurs de ω&#xa0;; intervalle le plus large %2 (bornes certifiées&#xa0;; la borne supérieure est exacte pour ce schéma interpolant)%3</translation>
    </message>
</context>
<context>
    <name>awb::RegularityPanel</name>
    <message>
        <source>Regularity: no curve scheme</source>
        <translation>Régularité&#xa0;: aucun schéma de courbe</translation>
    </message>
    <message>
        <source>Regularity %p%</source>
        <translation>Régularité %p&#xa0;%</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Stop the regularity analysis; the bounds reached so far stay</source>
        <translation>Arrêter l’analyse de régularité&#x202f;; les bornes déjà atteintes sont conservées</translation>
    </message>
    <message>
        <source>Regularity of %1: computing…</source>
        <translation>Régularité de %1&#xa0;: calcul en cours…</translation>
    </message>
    <message>
        <source>so far: r in [%1, %2]</source>
        <translation>pour l’instant&#xa0;: r dans [%1, %2]</translation>
    </message>
    <message>
        <source>Regularity: %1</source>
        <translation>Régularité&#xa0;: %1</translation>
    </message>
    <message>
        <source>Save Certificate…</source>
        <translation>Enregistrer le certificat…</translation>
    </message>
    <message>
        <source>The invariant polytope that proves the exponent, as JSON: attractor-cli verify-regularity re-checks it without any search</source>
        <translation>Le polytope invariant qui prouve l&apos;exposant, au format JSON&#xa0;: attractor-cli verify-regularity le revérifie sans aucune recherche</translation>
    </message>
</context>
<context>
    <name>awb::RemoveControlPointCommand</name>
    <message>
        <source>Remove a control point of %1</source>
        <translation>Supprimer un point de contrôle de %1</translation>
    </message>
</context>
<context>
    <name>awb::RemoveItemCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>Supprimer %1</translation>
    </message>
</context>
<context>
    <name>awb::SchemeFamily</name>
    <message>
        <source>a family has one or two parameters, got %1</source>
        <translation>une famille a un ou deux paramètres ; obtenu : %1</translation>
    </message>
    <message>
        <source>the two parameters have the same name &apos;%1&apos;</source>
        <translation>les deux paramètres portent le même nom « %1 »</translation>
    </message>
    <message>
        <source>a mask with parameters needs a mask item; this one is %1</source>
        <translation>un masque avec paramètres nécessite un élément masque ; celui-ci est %1</translation>
    </message>
    <message>
        <source>the parameter of a mask must be a name that is not a function or constant (pi, e, sqrt, ...), got &apos;%1&apos;</source>
        <translation>le paramètre d&apos;un masque doit être un nom qui n&apos;est ni une fonction ni une constante (pi, e, sqrt, ...) ; obtenu : « %1 »</translation>
    </message>
    <message>
        <source>the mask &apos;%1&apos; does not contain the parameter &apos;%2&apos;</source>
        <translation>le masque « %1 » ne contient pas le paramètre « %2 »</translation>
    </message>
    <message>
        <source>the scheme (%1) has no parameter &apos;%2&apos;: omega belongs to the four-point scheme, a and b to corner cutting; a mask item takes a mask with the parameter in its coefficients</source>
        <translation>le schéma (%1) n&apos;a pas de paramètre « %2 » : omega appartient au schéma à quatre points, a et b à la découpe des coins ; un élément masque prend un masque dont les coefficients contiennent le paramètre</translation>
    </message>
    <message>
        <source>expected %1 parameter values, got %2</source>
        <translation>%1 valeurs de paramètre attendues ; obtenu : %2</translation>
    </message>
    <message>
        <source>expected a list of names</source>
        <translation>une liste de noms est attendue</translation>
    </message>
    <message>
        <source>family: %1: %2</source>
        <translation>famille : %1 : %2</translation>
    </message>
    <message>
        <source>an atlas row has no value of &apos;%1&apos;</source>
        <translation>une ligne de l&apos;atlas n&apos;a pas de valeur pour « %1 »</translation>
    </message>
</context>
<context>
    <name>awb::SchemeRegularity</name>
    <message>
        <source>does not apply: a complex de Casteljau parameter is not a real subdivision scheme</source>
        <translation>sans objet&#xa0;: un paramètre de de Casteljau complexe ne définit pas un schéma de subdivision réel</translation>
    </message>
    <message>
        <source>does not apply: %1</source>
        <translation>sans objet&#xa0;: %1</translation>
    </message>
</context>
<context>
    <name>awb::ScriptRecorder</name>
    <message>
        <source>Undo</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Rétablir</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Modification</translation>
    </message>
</context>
<context>
    <name>awb::SpectrumView</name>
    <message>
        <source>Re λ</source>
        <translation>Re λ</translation>
    </message>
    <message>
        <source>Im λ</source>
        <translation>Im λ</translation>
    </message>
    <message>
        <source>unit circle</source>
        <translation>cercle unité</translation>
    </message>
    <message>
        <source>dominant 1</source>
        <translation>1 dominante</translation>
    </message>
    <message>
        <source>subdominant</source>
        <translation>sous-dominante</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: λ = %2, |λ| = %3, multiplicity %4, arg λ = %6° (map %5)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&#xa0;: λ = %2, |λ| = %3, multiplicité %4, arg λ = %6° (application %5)</translation>
    </message>
    <message>
        <source> — dominant</source>
        <translation> — dominante</translation>
    </message>
    <message>
        <source> — subdominant</source>
        <translation> — sous-dominante</translation>
    </message>
    <message>
        <source>&lt;p&gt;No maps.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Aucune application.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;All maps are (eventually) contractive&lt;/b&gt;: the IFS has a unique attractor.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Toutes les applications sont contractantes (à terme)&lt;/b&gt;&#xa0;: l’IFS a un unique attracteur.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;%1 is not contractive&lt;/b&gt;: the IFS has no attractor and its iteration does not converge.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;%1 n’est pas contractante&lt;/b&gt;&#xa0;: l’IFS n’a pas d’attracteur et son itération ne converge pas.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Not contractive: spectral radius %1 ≥ 1.</source>
        <translation>Non contractante&#xa0;: rayon spectral %1 ≥ 1.</translation>
    </message>
    <message>
        <source>Contractive: ‖A‖&lt;sub&gt;2&lt;/sub&gt; = %1 &amp;lt; 1.</source>
        <translation>Contractante&#xa0;: ‖A‖&lt;sub&gt;2&lt;/sub&gt; = %1 &amp;lt; 1.</translation>
    </message>
    <message>
        <source>Eventually contractive: spectral radius %1 &amp;lt; 1, ‖A&lt;sup&gt;%2&lt;/sup&gt;‖&lt;sub&gt;2&lt;/sub&gt; &amp;lt; 1.</source>
        <translation>Contractante à terme&#xa0;: rayon spectral %1 &amp;lt; 1, ‖A&lt;sup&gt;%2&lt;/sup&gt;‖&lt;sub&gt;2&lt;/sub&gt; &amp;lt; 1.</translation>
    </message>
    <message>
        <source>Eventually contractive: spectral radius %1 &amp;lt; 1.</source>
        <translation>Contractante à terme&#xa0;: rayon spectral %1 &amp;lt; 1.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>No subdominant eigenvalue: the map is constant.</source>
        <translation>Pas de valeur propre sous-dominante&#xa0;: l’application est constante.</translation>
    </message>
    <message>
        <source>real positive</source>
        <translation>réelle positive</translation>
    </message>
    <message>
        <source>The curve has a half-tangent at the fixed point, along the eigenvector (G¹ where the two sides&apos; eigenvectors align).</source>
        <translation>La courbe a une demi-tangente au point fixe, dirigée par le vecteur propre (G¹ là où les vecteurs propres des deux côtés sont alignés).</translation>
    </message>
    <message>
        <source>Repeated: the tangent direction at the fixed point depends on the control points.</source>
        <translation>Valeur propre multiple&#xa0;: la direction de la tangente au point fixe dépend des points de contrôle.</translation>
    </message>
    <message>
        <source>real negative</source>
        <translation>réelle négative</translation>
    </message>
    <message>
        <source>The curve oscillates at the fixed point and has no tangent there.</source>
        <translation>La courbe oscille au point fixe et n’y a pas de tangente.</translation>
    </message>
    <message>
        <source>complex pair</source>
        <translation>paire complexe</translation>
    </message>
    <message>
        <source>The curve spirals around the fixed point (no tangent).</source>
        <translation>La courbe s’enroule en spirale autour du point fixe (pas de tangente).</translation>
    </message>
    <message>
        <source>complex</source>
        <translation>complexe</translation>
    </message>
    <message>
        <source>Near the fixed point the map acts as the spiral similarity z ↦ λz: the curve spirals around the fixed point (no tangent).</source>
        <translation>Près du point fixe, l’application agit comme la similitude directe z ↦ λz&#xa0;: la courbe s’enroule en spirale autour du point fixe (pas de tangente).</translation>
    </message>
    <message>
        <source>mixed</source>
        <translation>mixte</translation>
    </message>
    <message>
        <source>Several eigenvalues of the same modulus with different signs or phases: no single tangent behaviour.</source>
        <translation>Plusieurs valeurs propres de même module avec des signes ou des phases différents&#xa0;: pas de comportement tangent unique.</translation>
    </message>
    <message>
        <source>Subdominant: none.</source>
        <translation>Sous-dominante&#xa0;: aucune.</translation>
    </message>
    <message>
        <source>Subdominant: %1 (%2, |λ| = %3, multiplicity %4).</source>
        <translation>Sous-dominante&#xa0;: %1 (%2, |λ| = %3, multiplicité %4).</translation>
    </message>
    <message>
        <source>Unknown file type “%1”: use .pdf, .svg or .png.</source>
        <translation>Type de fichier «&#xa0;%1&#xa0;» inconnu&#xa0;: utilisez .pdf, .svg ou .png.</translation>
    </message>
    <message>
        <source>Eigenvalues</source>
        <translation>Valeurs propres</translation>
    </message>
    <message>
        <source>%1: λ = %2</source>
        <translation>%1 : λ = %2</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;%1 is not contractive, but the IFS contracts on average&lt;/b&gt;: its Lyapunov exponent is %2 &amp;lt; 0 (Barnsley–Elton), so random iteration converges to its attractor, as in flame renderers; deterministic iteration does not.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;%1 n’est pas contractante, mais l’IFS est contractant en moyenne&lt;/b&gt;&#xa0;: son exposant de Lyapunov vaut %2 &amp;lt; 0 (Barnsley–Elton), donc l’itération aléatoire converge vers son attracteur, comme dans les logiciels de flammes fractales&#xa0;; l’itération déterministe ne converge pas.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>The spectra below are those of the xforms&apos; affine (pre) maps; the variations bend the maps, so the spectra alone say nothing of the flame&apos;s attractor.</source>
        <translation>Les spectres ci-dessous sont ceux des parties affines (pré) des xforms ; les variations courbent les applications, de sorte que les spectres seuls ne disent rien de l&apos;attracteur de la flamme.</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;The flame contracts on average&lt;/b&gt;: the top Lyapunov exponent of its chaos game along its own orbit is %1 &amp;lt; 0, so the game converges to its attractor. %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;La flamme contracte en moyenne&lt;/b&gt; : le plus grand exposant de Lyapunov de son jeu du chaos le long de sa propre orbite vaut %1 &amp;lt; 0, donc le jeu converge vers son attracteur. %2&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;The flame does not contract on average&lt;/b&gt;: the top Lyapunov exponent of its chaos game along its own orbit is %1 &amp;ge; 0, so its picture is not an attractor&apos;s. %2&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;La flamme ne contracte pas en moyenne&lt;/b&gt; : le plus grand exposant de Lyapunov de son jeu du chaos le long de sa propre orbite vaut %1 &amp;ge; 0, donc son image n&apos;est pas celle d&apos;un attracteur. %2&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>awb::StartSetSpec</name>
    <message>
        <source>a lifted start set needs at least one point</source>
        <translation>un ensemble initial relevé demande au moins un point</translation>
    </message>
    <message>
        <source>lifted start point %1 has %2 coordinates: every point needs the same number, at least 2</source>
        <translation>le point initial relevé %1 a %2 coordonnées&#xa0;: tous les points doivent en avoir le même nombre, au moins 2</translation>
    </message>
    <message>
        <source>every point must have finite coordinates</source>
        <translation>tous les points doivent avoir des coordonnées finies</translation>
    </message>
    <message>
        <source>a start set of kind &quot;%1&quot; needs exactly %2 points, got %3</source>
        <translation>un ensemble initial de type &quot;%1&quot; demande exactement %2 points (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>a start set of kind &quot;%1&quot; needs at least %2 points, got %3</source>
        <translation>un ensemble initial de type &quot;%1&quot; demande au moins %2 points (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>a start set of net points needs at least one index</source>
        <translation>un ensemble initial de points du réseau demande au moins un indice</translation>
    </message>
    <message>
        <source>a start set of net points takes at most %1 indices, got %2</source>
        <translation>un ensemble initial de points du réseau prend au plus %1 indices, reçu %2</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2: indices count from 0</source>
        <translation>le point de réseau %1 de l’ensemble initial a l’indice %2 : les indices commencent à 0</translation>
    </message>
</context>
<context>
    <name>awb::StartSetText</name>
    <message>
        <source>&apos;%1&apos; is not a finite number</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>a start set is written point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | vertex-limits, got &apos;%1&apos;</source>
        <translation type="vanished">un ensemble initial s’écrit point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | vertex-limits, reçu « %1 »</translation>
    </message>
    <message>
        <source>a %1 needs %2 coordinates (%3 per point), got %4</source>
        <translation>un %1 demande %2 coordonnées (%3 par point), reçu %4</translation>
    </message>
    <message>
        <source>a multiple of %1</source>
        <translation>un multiple de %1</translation>
    </message>
    <message>
        <source>lifted: needs at least one point</source>
        <translation>lifted: demande au moins un point</translation>
    </message>
    <message>
        <source>vertex-limits needs a mesh item; &apos;%1&apos; is a %2</source>
        <translation>vertex-limits demande un élément maillage ; « %1 » est un %2</translation>
    </message>
    <message>
        <source>a start set is written point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | net:i,j,... | vertex-limits, got &apos;%1&apos;</source>
        <translation>un ensemble initial s’écrit point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | net:i,j,... | vertex-limits, reçu « %1 »</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a net point index (an integer from 0)</source>
        <translation>« %1 » n’est pas un indice de point du réseau (un entier à partir de 0)</translation>
    </message>
    <message>
        <source>net: needs at least one index</source>
        <translation>net: demande au moins un indice</translation>
    </message>
</context>
<context>
    <name>awb::StyleSpec</name>
    <message>
        <source>the density gamma must be between 0.2 and 10, got %1</source>
        <translation>le gamma de densité doit être compris entre 0,2 et 10 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the address prefix length must be between 1 and %1, got %2</source>
        <translation>la longueur du préfixe d’adresse doit être comprise entre 1 et %1 (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>the point size must be more than 0 and at most %1 pixels</source>
        <translation>la taille des points doit être strictement positive et d’au plus %1 pixels</translation>
    </message>
    <message>
        <source>colour %1 is &quot;%2&quot;, expected &quot;#rrggbb&quot; (lower-case hexadecimal)</source>
        <translation>la couleur %1 vaut &quot;%2&quot;, &quot;#rrggbb&quot; attendu (hexadécimal en minuscules)</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionCurveItem</name>
    <message>
        <source>Bézier of degree %1 needs exactly %2 control points, got %3</source>
        <translation>une courbe de Bézier de degré %1 demande exactement %2 points de contrôle (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>a complex Bézier parameter has no real scheme</source>
        <translation>un paramètre de Bézier complexe n’a pas de schéma réel</translation>
    </message>
    <message>
        <source>unknown scheme kind</source>
        <translation>type de schéma inconnu</translation>
    </message>
    <message>
        <source>the complex parameter t = %1 %2 %3i must satisfy |t| &lt; 1 and |1 - t| &lt; 1 (004 §3.7)</source>
        <translation>le paramètre complexe t = %1 %2 %3i doit vérifier |t| &lt; 1 et |1 - t| &lt; 1 (004 §3.7)</translation>
    </message>
    <message>
        <source>Curve</source>
        <translation>Courbe</translation>
    </message>
    <message>
        <source>Change scheme of %1</source>
        <translation>Modifier le schéma de %1</translation>
    </message>
    <message>
        <source>expected [re, im] or a number</source>
        <translation>[re, im] ou nombre attendu</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Uniform B-spline</source>
        <translation>B-spline uniforme</translation>
    </message>
    <message>
        <source>End-interpolating B-spline</source>
        <translation>B-spline interpolant les extrémités</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Corner cutting</source>
        <translation>Découpe de coins</translation>
    </message>
    <message>
        <source>Four-point</source>
        <translation>Quatre points</translation>
    </message>
    <message>
        <source>Bézier (de Casteljau)</source>
        <translation>Bézier (de Casteljau)</translation>
    </message>
    <message>
        <source>Own matrices</source>
        <translation>Matrices personnalisées</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Degré</translation>
    </message>
    <message>
        <source>Degree n: the curve has n + 1 control points</source>
        <translation>Degré n&#xa0;: la courbe a n + 1 points de contrôle</translation>
    </message>
    <message>
        <source>Degree of the B-spline (Lane–Riesenfeld, 004 eq. 2.7)</source>
        <translation>Degré de la B-spline (Lane–Riesenfeld, 004 éq. 2.7)</translation>
    </message>
    <message>
        <source>Split parameter t</source>
        <translation>Paramètre de découpe t</translation>
    </message>
    <message>
        <source>de Casteljau split at t (004 eq. 2.5). A complex t inside both discs |t| &lt; 1, |1 − t| &lt; 1 gives a fractal curve (004 §3.7).</source>
        <translation>Découpe de de Casteljau en t (004 éq. 2.5). Un t complexe à l’intérieur des deux disques |t| &lt; 1, |1 − t| &lt; 1 donne une courbe fractale (004 §3.7).</translation>
    </message>
    <message>
        <source>Tension ω</source>
        <translation>Tension ω</translation>
    </message>
    <message>
        <source>1/16 gives C1 curves reproducing cubics; −1/2 &lt; ω &lt; 0 or 1/4 ≤ ω &lt; 1/2 gives fractal curves (004 Thm. 2.4.1)</source>
        <translation>1/16 donne des courbes C1 qui reproduisent les cubiques&#x202f;; −1/2 &lt; ω &lt; 0 ou 1/4 ≤ ω &lt; 1/2 donne des courbes fractales (004 th. 2.4.1)</translation>
    </message>
    <message>
        <source>New points at parameters a &lt; b on every edge (Chaikin: 1/4, 3/4)</source>
        <translation>Nouveaux points aux paramètres a &lt; b sur chaque arête (Chaikin&#xa0;: 1/4, 3/4)</translation>
    </message>
    <message>
        <source>First cut a</source>
        <translation>Première coupe a</translation>
    </message>
    <message>
        <source>Second cut b</source>
        <translation>Seconde coupe b</translation>
    </message>
    <message>
        <source>Subdivision curve</source>
        <translation>Courbe de subdivision</translation>
    </message>
    <message>
        <source>mask entry %1, &quot;%2&quot;, is not a number (fractions such as 3/8 and expressions such as (1 + sqrt(3))/8 are)</source>
        <translation>l&apos;entrée %1 du masque, &quot;%2&quot;, n&apos;est pas un nombre (les fractions comme 3/8 et les expressions comme (1 + sqrt(3))/8 en sont)</translation>
    </message>
    <message>
        <source>no sum rule: σ(z) = %1 does not divide the symbol a(z), so the scheme has no difference scheme and cannot converge</source>
        <translation>aucune règle de somme&#xa0;: σ(z) = %1 ne divise pas le symbole a(z), le schéma n&apos;a donc pas de schéma aux différences et ne peut pas converger</translation>
    </message>
    <message>
        <source>1 sum rule</source>
        <translation>1 règle de somme</translation>
    </message>
    <message>
        <source>%1 sum rules</source>
        <translation>%1 règles de somme</translation>
    </message>
    <message>
        <source>%1: a(z) = σ(z)%2 b(z) / %3%2 with σ(z) = %4 and b = (%5) from z%6</source>
        <translation>%1&#xa0;: a(z) = σ(z)%2 b(z) / %3%2 avec σ(z) = %4 et b = (%5) à partir de z%6</translation>
    </message>
    <message>
        <source>expected a non-empty array of coefficients</source>
        <translation>un tableau non vide de coefficients était attendu</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Masque</translation>
    </message>
    <message>
        <source>Arity N</source>
        <translation>Arité N</translation>
    </message>
    <message>
        <source>Each step makes N new points per old one. A new arity whose cosets the mask does not fit starts from the N-ary piecewise linear mask.</source>
        <translation>Chaque étape crée N nouveaux points par ancien point. Pour une nouvelle arité dont les classes résiduelles ne conviennent pas au masque, on repart du masque N-aire linéaire par morceaux.</translation>
    </message>
    <message>
        <source>Mask a_k</source>
        <translation>Masque a_k</translation>
    </message>
    <message>
        <source>q_n = Σ a_(n − N l) p_l. Separate the coefficients by commas (by semicolons to use decimal commas); fractions (3/8) and expressions ((1 + sqrt(3))/8) are kept as typed. Each of the N cosets a_(r + N k) must sum to 1.</source>
        <translation>q_n = Σ a_(n − N l) p_l. Séparez les coefficients par des virgules (par des points-virgules pour utiliser la virgule décimale)&#xa0;; les fractions (3/8) et les expressions ((1 + sqrt(3))/8) sont conservées telles que saisies. Chacune des N classes résiduelles a_(r + N k) doit avoir pour somme 1.</translation>
    </message>
    <message>
        <source>First index k</source>
        <translation>Premier indice k</translation>
    </message>
    <message>
        <source>The index of the mask&apos;s first coefficient: the cubic B-spline is 1/8, 1/2, 3/4, 1/2, 1/8 from k = −2</source>
        <translation>L&apos;indice du premier coefficient du masque&#xa0;: la B-spline cubique est 1/8, 1/2, 3/4, 1/2, 1/8 à partir de k = −2</translation>
    </message>
    <message>
        <source>Symbol</source>
        <translation>Symbole</translation>
    </message>
    <message>
        <source>The symbol a(z) = Σ a_k z^k divided by σ(z) = 1 + z + … + z^(N−1) as often as it goes: each factor is one sum rule (polynomials of one more degree reproduced, one more difference scheme)</source>
        <translation>Le symbole a(z) = Σ a_k z^k divisé par σ(z) = 1 + z + … + z^(N−1) autant de fois que possible&#xa0;: chaque facteur est une règle de somme (reproduction des polynômes d&apos;un degré de plus, un schéma aux différences de plus)</translation>
    </message>
    <message>
        <source>the symbol follows from the mask: edit the mask</source>
        <translation type="vanished">le symbole découle du masque&#xa0;: modifiez le masque</translation>
    </message>
    <message>
        <source>Matrices S_i</source>
        <translation>Matrices S_i</translation>
    </message>
    <message>
        <source>The subdivision matrices S_1 .. S_p, m x m with rows summing to 1; edited cell by cell in the Matrices dock</source>
        <translation>Les matrices de subdivision S_1 .. S_p, de taille m x m, chaque ligne ayant pour somme 1&#x202f;; modifiables cellule par cellule dans le panneau Matrices</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Points de contrôle</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionMeshItem</name>
    <message>
        <source>Mesh surface</source>
        <translation>Surface de maillage</translation>
    </message>
    <message>
        <source>Change mesh of %1</source>
        <translation>Modifier le maillage de %1</translation>
    </message>
    <message>
        <source>a mesh surface is drawn by deterministic iteration: random iteration of its pieces is not implemented</source>
        <translation>une surface de maillage est tracée par itération déterministe&#xa0;: l’itération aléatoire de ses morceaux n’est pas implémentée</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after %3 isolating steps (docs/mathematics.md, &quot;Extraordinary vertices&quot;)</source>
        <translation type="vanished">%1 morceaux de %2 types après %3 étapes d’isolement (docs/mathematics.md, &quot;Extraordinary vertices&quot;)</translation>
    </message>
    <message>
        <source>expected an array of faces, each an array of vertex numbers</source>
        <translation>tableau de faces attendu, chacune étant un tableau de numéros de sommets</translation>
    </message>
    <message>
        <source>expected a face: an array of vertex numbers (0-based)</source>
        <translation>face attendue&#xa0;: un tableau de numéros de sommets (numérotés à partir de 0)</translation>
    </message>
    <message>
        <source>vertex numbers are whole numbers (0-based)</source>
        <translation>les numéros de sommets sont des entiers (numérotés à partir de 0)</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Catmull–Clark</source>
        <translation>Catmull–Clark</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Loop</translation>
    </message>
    <message>
        <source>Loop takes triangle meshes only</source>
        <translation>Loop ne prend que des maillages triangulaires</translation>
    </message>
    <message>
        <source>Colours</source>
        <translation type="vanished">Couleurs</translation>
    </message>
    <message>
        <source>By map</source>
        <translation>Par application</translation>
    </message>
    <message>
        <source>By level around extraordinary vertices</source>
        <translation>Par niveau autour des sommets extraordinaires</translation>
    </message>
    <message>
        <source>Style</source>
        <translation>Style</translation>
    </message>
    <message>
        <source>a mesh has no single lifted space: each of its pieces is lifted over its own control net</source>
        <translation>un maillage n’a pas d’espace relevé unique&#xa0;: chacun de ses morceaux est relevé sur son propre réseau de contrôle</translation>
    </message>
    <message>
        <source>By level: around an extraordinary vertex, the rings C, f(C), f²(C), … of its IFS with condensation get colours in turn</source>
        <translation>Par niveau&#xa0;: autour d’un sommet extraordinaire, les anneaux C, f(C), f²(C), … de son IFS avec condensation reçoivent tour à tour une couleur</translation>
    </message>
    <message>
        <source>the steps before the limit positions must be 0 to %1, got %2</source>
        <translation>le nombre d’étapes avant les positions limites doit être de 0 à %1, reçu %2</translation>
    </message>
    <message>
        <source>%1 steps give about %2 vertices: more than %3</source>
        <translation>%1 étapes donnent environ %2 sommets&#xa0;: plus de %3</translation>
    </message>
    <message>
        <source>Attractor Workbench: item %1, %2 after %3 steps, every vertex at its limit position</source>
        <translation>Attractor Workbench&#xa0;: élément %1, %2 après %3 étapes, chaque sommet à sa position limite</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Sommets</translation>
    </message>
    <message>
        <source>The mesh&apos;s vertices [x, y, z]: its control points</source>
        <translation>Les sommets du maillage [x, y, z]&#xa0;: ses points de contrôle</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>Faces</translation>
    </message>
    <message>
        <source>Each face as the loop of its vertex numbers (0-based)</source>
        <translation>Chaque face sous la forme de la boucle des numéros de ses sommets (numérotés à partir de 0)</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after %3 steps that isolate the extraordinary vertices</source>
        <translation>%1 morceaux de %2 types après %3 étapes qui isolent les sommets extraordinaires</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after one step that isolates the extraordinary vertices</source>
        <translation>%1 morceaux de %2 types après une étape qui isole les sommets extraordinaires</translation>
    </message>
    <message>
        <source>Pieces coloured</source>
        <translation>Coloration des morceaux</translation>
    </message>
    <message>
        <source>expected an array, each entry %1</source>
        <translation>tableau attendu, chaque entrée étant %1</translation>
    </message>
    <message>
        <source>expected %1</source>
        <translation>attendu : %1</translation>
    </message>
    <message>
        <source>vertex and face numbers are whole numbers (0-based)</source>
        <translation>les numéros de sommets et de faces sont des entiers (numérotés à partir de 0)</translation>
    </message>
    <message>
        <source>a sharpness is a number of 0 or more (10 or more: infinitely sharp)</source>
        <translation>une netteté est un nombre positif ou nul (10 ou plus : infiniment vive)</translation>
    </message>
    <message>
        <source>a crease: [first vertex, second vertex, sharpness]</source>
        <translation>une arête vive sous la forme [premier sommet, second sommet, netteté]</translation>
    </message>
    <message>
        <source>Creases</source>
        <translation>Arêtes vives</translation>
    </message>
    <message>
        <source>Sharp features</source>
        <translation>Éléments vifs</translation>
    </message>
    <message>
        <source>Sharp edges as [first vertex, second vertex, sharpness]: sharp for that many levels (10 or more: for ever), as OpenSubdiv&apos;s creases</source>
        <translation>Arêtes vives sous la forme [premier sommet, second sommet, netteté] : vives pendant autant de niveaux (10 ou plus : pour toujours), comme les arêtes vives (creases) d’OpenSubdiv</translation>
    </message>
    <message>
        <source>a corner: [vertex, sharpness]</source>
        <translation>un coin sous la forme [sommet, netteté]</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Coins</translation>
    </message>
    <message>
        <source>Sharp vertices as [vertex, sharpness]: the surface passes through them while the sharpness lasts</source>
        <translation>Sommets vifs sous la forme [sommet, netteté] : la surface passe par ces sommets tant que dure leur netteté</translation>
    </message>
    <message>
        <source>a face number (0-based)</source>
        <translation>un numéro de face (numéroté à partir de 0)</translation>
    </message>
    <message>
        <source>Holes</source>
        <translation>Trous</translation>
    </message>
    <message>
        <source>Faces (0-based) left out of the surface; they still shape their neighbours</source>
        <translation>Faces (numérotées à partir de 0) exclues de la surface ; elles influent toujours sur la forme de leurs voisines</translation>
    </message>
    <message>
        <source>None (faces at the boundary are left out)</source>
        <translation>Aucun (les faces du bord sont omises)</translation>
    </message>
    <message>
        <source>Edges</source>
        <translation>Arêtes</translation>
    </message>
    <message>
        <source>Edges and corners</source>
        <translation>Arêtes et coins</translation>
    </message>
    <message>
        <source>Boundary</source>
        <translation>Bord</translation>
    </message>
    <message>
        <source>How the boundary is interpolated (OpenSubdiv&apos;s VtxBoundaryInterpolation): with corners, a vertex of one face is a corner of the surface</source>
        <translation>Mode d’interpolation du bord (VtxBoundaryInterpolation d’OpenSubdiv) : avec les coins, un sommet qui n’appartient qu’à une seule face devient un coin de la surface</translation>
    </message>
    <message>
        <source>Uniform</source>
        <translation>Uniforme</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Crease method</source>
        <translation>Méthode des arêtes vives</translation>
    </message>
    <message>
        <source>How a semi-sharp crease decays: by 1 per level, or Chaikin&apos;s average with its neighbours</source>
        <translation>Décroissance d’une arête semi-vive : de 1 par niveau, ou par la moyenne de Chaikin avec ses voisines</translation>
    </message>
    <message>
        <source>Smooth triangles</source>
        <translation>Triangles lisses</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>Catmull–Clark&apos;s edge points next to triangles: as for any face, or OpenSubdiv&apos;s smoother weights</source>
        <translation>Points d’arête de Catmull–Clark voisins de triangles : comme pour toute autre face, ou avec les poids plus lisses d’OpenSubdiv</translation>
    </message>
    <message>
        <source>face %1: the mesh has %2 faces (0 to %3)</source>
        <translation>face %1 : le maillage a %2 faces (0 à %3)</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionSurfaceItem</name>
    <message>
        <source>Surface</source>
        <translation>Surface</translation>
    </message>
    <message>
        <source>Change net of %1</source>
        <translation>Modifier le réseau de %1</translation>
    </message>
    <message>
        <source>Change subdivision rounds of %1</source>
        <translation>Modifier le nombre de passes de subdivision de %1</translation>
    </message>
    <message>
        <source>Turn the view of %1</source>
        <translation>Faire pivoter la vue de %1</translation>
    </message>
    <message>
        <source>expected an array of lattice coordinates [i, j]</source>
        <translation>tableau de coordonnées de grille [i, j] attendu</translation>
    </message>
    <message>
        <source>expected lattice coordinates [i, j]</source>
        <translation>coordonnées de grille [i, j] attendues</translation>
    </message>
    <message>
        <source>lattice coordinates are whole numbers</source>
        <translation>les coordonnées de grille sont des entiers</translation>
    </message>
    <message>
        <source>at least one map must be used (leave the field out to use all)</source>
        <translation>au moins une application doit être utilisée (omettez le champ pour les utiliser toutes)</translation>
    </message>
    <message>
        <source>map indices are whole numbers (0-based)</source>
        <translation>les indices d’application sont des entiers (numérotés à partir de 0)</translation>
    </message>
    <message>
        <source>the elevation must be from -90 to 90 degrees</source>
        <translation>l’élévation doit être comprise entre -90 et 90 degrés</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Bicubic B-spline (Catmull–Clark)</source>
        <translation>B-spline bicubique (Catmull–Clark)</translation>
    </message>
    <message>
        <source>Loop (three-direction box spline)</source>
        <translation>Loop (box-spline à trois directions)</translation>
    </message>
    <message>
        <source>Kobbelt √3</source>
        <translation>Kobbelt √3</translation>
    </message>
    <message>
        <source>A new scheme starts from its own default net (000 §3)</source>
        <translation>Un nouveau schéma part de son propre réseau par défaut (000 §3)</translation>
    </message>
    <message>
        <source>Layout</source>
        <translation>Disposition</translation>
    </message>
    <message>
        <source>The patch&apos;s domain and the maps covering it</source>
        <translation>Le domaine du carreau et les applications qui le recouvrent</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>Applications</translation>
    </message>
    <message>
        <source>Map %1</source>
        <translation>Application %1</translation>
    </message>
    <message>
        <source>Leave maps out to draw a fractal lying on the surface (000 Fig. 9)</source>
        <translation>Omettez des applications pour tracer une fractale posée sur la surface (000 fig. 9)</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Vue</translation>
    </message>
    <message>
        <source>Azimuth</source>
        <translation>Azimut</translation>
    </message>
    <message>
        <source>Direction of the orthographic camera around the z axis, in degrees</source>
        <translation>Direction de la caméra orthographique autour de l’axe z, en degrés</translation>
    </message>
    <message>
        <source>Elevation</source>
        <translation>Élévation</translation>
    </message>
    <message>
        <source>Height of the camera above the xy plane, in degrees</source>
        <translation>Hauteur de la caméra au-dessus du plan xy, en degrés</translation>
    </message>
    <message>
        <source>Subdivision rounds</source>
        <translation>Passes de subdivision</translation>
    </message>
    <message>
        <source>Rounds of classic subdivision of the net (000 Figs. 6–8, top)</source>
        <translation>Passes de subdivision classique du réseau (000 fig. 6–8, en haut)</translation>
    </message>
    <message>
        <source>from 0 to %1 rounds</source>
        <translation>de 0 à %1 passes</translation>
    </message>
    <message>
        <source>at least one map must stay on</source>
        <translation>au moins une application doit rester active</translation>
    </message>
    <message>
        <source>Subdivision surface</source>
        <translation>Surface de subdivision</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Points de contrôle</translation>
    </message>
    <message>
        <source>Lattice coordinates</source>
        <translation>Coordonnées de grille</translation>
    </message>
    <message>
        <source>Each control point&apos;s place [i, j] on the scheme&apos;s lattice</source>
        <translation>La position [i, j] de chaque point de contrôle sur la grille du schéma</translation>
    </message>
    <message>
        <source>Maps used</source>
        <translation>Applications utilisées</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceNet</name>
    <message>
        <source>every control point must have finite coordinates</source>
        <translation>chaque point de contrôle doit avoir des coordonnées finies</translation>
    </message>
    <message>
        <source>%1 lattice coordinates for %2 control points: give one [i, j] per control point</source>
        <translation>%1 coordonnées de grille pour %2 points de contrôle&#xa0;: donnez un [i, j] par point de contrôle</translation>
    </message>
    <message>
        <source>not the net of a %1 %2 patch: %3</source>
        <translation>ce n’est pas le réseau d’un carreau %1 %2&#xa0;: %3</translation>
    </message>
    <message>
        <source>map %1 does not exist: the %2 layout has maps 0 to %3</source>
        <translation>l’application %1 n’existe pas&#xa0;: la disposition %2 a les applications 0 à %3</translation>
    </message>
    <message>
        <source>list each map once, in increasing order (0-based)</source>
        <translation>listez chaque application une seule fois, par ordre croissant (à partir de 0)</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceSchemeSpec</name>
    <message>
        <source>the %1 scheme has the layouts %2, not &apos;%3&apos;</source>
        <translation>le schéma %1 a les dispositions %2, pas «&#xa0;%3&#xa0;»</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceView</name>
    <message>
        <source>Drawing… (CPU renderer)</source>
        <translation>Tracé… (rendu CPU)</translation>
    </message>
    <message>
        <source>CPU renderer</source>
        <translation>Rendu CPU</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>depth %1 of %2 (detail budget: %3 k primitives) · %4</source>
        <translation>profondeur %1 sur %2 (budget de détail&#xa0;: %3 k primitives) · %4</translation>
    </message>
</context>
<context>
    <name>awb::UserGuideDialog</name>
    <message>
        <source>&lt;p&gt;The guide is missing.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Le guide est introuvable.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Home or F</source>
        <translation>Home ou F</translation>
    </message>
    <message>
        <source>Fit the attractor view to its content</source>
        <translation>Ajuster la vue de l’attracteur à son contenu</translation>
    </message>
    <message>
        <source>+ / −</source>
        <translation>+ / −</translation>
    </message>
    <message>
        <source>Zoom the attractor view in / out</source>
        <translation>Zoom avant / arrière dans la vue de l’attracteur</translation>
    </message>
    <message>
        <source>Mouse wheel</source>
        <translation>Molette de la souris</translation>
    </message>
    <message>
        <source>Zoom at the cursor (view); scroll (panels)</source>
        <translation>Zoomer autour du curseur (vue)&#x202f;; faire défiler (panneaux)</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>Guide de l’utilisateur</translation>
    </message>
</context>
<context>
    <name>awb::ValenceChart</name>
    <message>
        <source>Valences: choose a mesh surface</source>
        <translation>Valences&#xa0;: choisissez une surface de maillage</translation>
    </message>
    <message>
        <source>λ (subdominant)</source>
        <translation>λ (sous-dominante)</translation>
    </message>
    <message>
        <source>μ = |λ₄|</source>
        <translation>μ = |λ₄|</translation>
    </message>
    <message>
        <source>λ²</source>
        <translation>λ²</translation>
    </message>
    <message>
        <source>this mesh</source>
        <translation>ce maillage</translation>
    </message>
    <message>
        <source>λ, μ, λ² against n (%1)</source>
        <translation>λ, μ, λ² en fonction de n (%1)</translation>
    </message>
    <message>
        <source>The subdominant eigenvalue λ, the next modulus μ and λ² of the local subdivision matrix at an interior vertex of valence n; the purple dots are this mesh&apos;s valences</source>
        <translation>La valeur propre sous-dominante λ, le module suivant μ et λ² de la matrice de subdivision locale en un sommet intérieur de valence n&#x202f;; les points violets sont les valences de ce maillage</translation>
    </message>
    <message>
        <source>valence n</source>
        <translation>valence n</translation>
    </message>
    <message>
        <source>μ = λ² (bounded curvature)</source>
        <translation>μ = λ² (courbure bornée)</translation>
    </message>
    <message>
        <source>n = %1 … %2</source>
        <translation>n = %1 … %2</translation>
    </message>
    <message>
        <source>μ against λ²</source>
        <translation>μ en fonction de λ²</translation>
    </message>
    <message>
        <source>Below the diagonal (μ &lt; λ²) the curvature at the vertex is zero, on it bounded, above it unbounded (for generic data)</source>
        <translation>Sous la diagonale (μ &lt; λ²), la courbure au sommet est nulle, sur la diagonale bornée, au-dessus non bornée (pour des données génériques)</translation>
    </message>
    <message>
        <source>μ</source>
        <translation>μ</translation>
    </message>
    <message>
        <source>λ, μ, λ² (%1)</source>
        <translation>λ, μ, λ² (%1)</translation>
    </message>
</context>
<context>
    <name>awb::VertexPanel</name>
    <message>
        <source>Loop</source>
        <translation>Loop</translation>
    </message>
    <message>
        <source>Catmull–Clark</source>
        <translation>Catmull–Clark</translation>
    </message>
    <message>
        <source>New Eigenvalue Plot of This Vertex</source>
        <translation type="vanished">Nouveau diagramme des valeurs propres de ce sommet</translation>
    </message>
    <message>
        <source>Adds an eigenvalue plot item whose source is this extraordinary vertex: its local subdivision matrix&apos;s eigenvalues, kept in the project and printed with it</source>
        <translation>Ajoute un élément diagramme des valeurs propres dont la source est ce sommet extraordinaire&#xa0;: les valeurs propres de sa matrice de subdivision locale, conservées dans le projet et imprimées avec lui</translation>
    </message>
    <message>
        <source>Click an extraordinary vertex (a purple diamond labelled with its valence) in the 3D view of a mesh surface: its spectrum, Reif&apos;s verdict and its characteristic map appear here.</source>
        <translation>Cliquez sur un sommet extraordinaire (un losange violet étiqueté par sa valence) dans la vue 3D d’une surface de maillage&#xa0;: son spectre, le verdict de Reif et son application caractéristique s’affichent ici.</translation>
    </message>
    <message>
        <source>valence %1, %2, %3</source>
        <translation type="vanished">valence %1, %2, %3</translation>
    </message>
    <message>
        <source>on the boundary</source>
        <translation>sur le bord</translation>
    </message>
    <message>
        <source>interior</source>
        <translation>intérieur</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the net of the vertex&apos;s piece).</source>
        <translation>Matrice de subdivision locale S&#xa0;: %1 × %1 (le réseau du morceau du sommet).</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the vertex and every point within two faces of it).</source>
        <translation>Matrice de subdivision locale S&#xa0;: %1 × %1 (le sommet et tous les points situés à deux faces au plus de celui-ci).</translation>
    </message>
    <message>
        <source>λ₁ = 1, λ = %1, μ = %2, λ² = %3</source>
        <translation>λ₁ = 1, λ = %1, μ = %2, λ² = %3</translation>
    </message>
    <message>
        <source> (λ in closed form: %1)</source>
        <translation type="vanished"> (λ sous forme close&#xa0;: %1)</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for interior vertices only: a boundary vertex follows the crease rules, whose analysis needs the boundary&apos;s own characteristic map.</source>
        <translation type="vanished">Le critère de Reif n’est évalué ici que pour les sommets intérieurs&#xa0;: un sommet de bord suit les règles d’arête vive, dont l’analyse demande l’application caractéristique propre au bord.</translation>
    </message>
    <message>
        <source>spectral condition 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ real</source>
        <translation>condition spectrale 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ réel</translation>
    </message>
    <message>
        <source>characteristic map regular: the Jacobian keeps one sign on all %1 cells (signed areas %2 … %3)</source>
        <translation>application caractéristique régulière&#xa0;: le jacobien garde un signe constant sur les %1 cellules (aires signées %2 … %3)</translation>
    </message>
    <message>
        <source>characteristic map not regular: signed areas from %1 to %2</source>
        <translation>application caractéristique non régulière&#xa0;: aires signées de %1 à %2</translation>
    </message>
    <message>
        <source>characteristic map injective: its boundary winds %1 time(s) around the vertex</source>
        <translation>application caractéristique injective&#xa0;: son bord fait %1 tour(s) autour du sommet</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): the limit surface is C¹ at the vertex (for generic data).</source>
        <translation>Verdict (Reif 1995)&#xa0;: la surface limite est C¹ au sommet (pour des données génériques).</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): C¹ is not established at the vertex.</source>
        <translation>Verdict (Reif 1995)&#xa0;: la régularité C¹ au sommet n’est pas établie.</translation>
    </message>
    <message>
        <source>μ &lt; λ²: the curvature is zero at the vertex (the surface is flat there to second order, for generic data: no convex or saddle shape can be modelled at it)</source>
        <translation>μ &lt; λ²&#xa0;: la courbure est nulle au sommet (pour des données génériques, la surface y est plate au second ordre&#xa0;: aucune forme convexe ou en selle ne peut y être modélisée)</translation>
    </message>
    <message>
        <source>μ = λ²: the curvature is bounded at the vertex</source>
        <translation>μ = λ²&#xa0;: la courbure est bornée au sommet</translation>
    </message>
    <message>
        <source>μ &gt; λ²: the curvature is unbounded at the vertex (for generic data)</source>
        <translation>μ &gt; λ²&#xa0;: la courbure n’est pas bornée au sommet (pour des données génériques)</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3), normal (%4, %5, %6).</source>
        <translation>Position limite (%1, %2, %3), normale (%4, %5, %6).</translation>
    </message>
    <message>
        <source>New Eigenvalue Plot</source>
        <translation>Nouveau diagramme des valeurs propres</translation>
    </message>
    <message>
        <source>; in closed form λ = %1 = %2</source>
        <translation>; sous forme close λ = %1 = %2</translation>
    </message>
    <message>
        <source>No spectrum: %1.</source>
        <translation>Pas de spectre&#xa0;: %1.</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3).</source>
        <translation>Position limite (%1, %2, %3).</translation>
    </message>
    <message>
        <source>a dart (one sharp edge ends here)</source>
        <translation>un dard (une seule arête vive s’y termine)</translation>
    </message>
    <message>
        <source>on a crease</source>
        <translation>sur une arête vive</translation>
    </message>
    <message>
        <source>a corner</source>
        <translation>un coin</translation>
    </message>
    <message>
        <source>smooth</source>
        <translation>lisse</translation>
    </message>
    <message>
        <source>valence %1, %2, %3, %4</source>
        <translation>valence %1, %2, %3, %4</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for smooth interior vertices only: a boundary vertex or a sharp feature follows the crease rules, whose analysis needs the half-ring&apos;s own characteristic map.</source>
        <translation type="vanished">Le critère de Reif n’est évalué ici que pour les sommets intérieurs lisses : un sommet de bord ou un élément vif suit les règles d’arête vive, dont l’analyse demande l’application caractéristique propre au demi-anneau.</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion sector by sector (Zorin 2000): each run of faces between sharp edges, with the eigenvalues whose eigenvectors do not vanish on it, on the canonical star of this neighbourhood:</source>
        <translation>Critère de Reif secteur par secteur (Zorin 2000) : chaque suite de faces entre arêtes vives, avec les valeurs propres dont les vecteurs propres ne s’y annulent pas, sur l’étoile canonique de ce voisinage :</translation>
    </message>
    <message>
        <source>face %1</source>
        <translation>face %1</translation>
    </message>
    <message>
        <source>faces %1–%2</source>
        <translation>faces %1–%2</translation>
    </message>
    <message>
        <source>%1: λ₁ = %2, λ₂ = %3, μ = %4</source>
        <translation>%1 : λ₁ = %2, λ₂ = %3, μ = %4</translation>
    </message>
    <message>
        <source>; C¹, curvature %1</source>
        <translation> ; C¹, courbure %1</translation>
    </message>
    <message>
        <source>; not C¹: %1</source>
        <translation> ; pas C¹ : %1</translation>
    </message>
    <message>
        <source>; %1</source>
        <translation> ; %1</translation>
    </message>
    <message>
        <source>Verdict: the limit surface is C¹ on every sector up to the creases (for generic data).</source>
        <translation>Verdict : la surface limite est C¹ sur chaque secteur jusqu’aux plis (pour des données génériques).</translation>
    </message>
    <message>
        <source>Verdict: C¹ is not established on every sector.</source>
        <translation>Verdict : C¹ n’est pas établi sur chaque secteur.</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided for valences 3 to 64: this vertex is outside them.</source>
        <translation>Le critère de Reif est décidé pour les valences 3 à 64 : ce sommet est en dehors.</translation>
    </message>
    <message>
        <source>zero (μ &lt; λ₂²)</source>
        <translation>nulle (μ &lt; λ₂²)</translation>
    </message>
    <message>
        <source>bounded (μ = λ₂²)</source>
        <translation>bornée (μ = λ₂²)</translation>
    </message>
    <message>
        <source>unbounded (μ &gt; λ₂²)</source>
        <translation>non bornée (μ &gt; λ₂²)</translation>
    </message>
</context>
<context>
    <name>awb::analysis</name>
    <message>
        <source>cannot index an empty point set</source>
        <translation>impossible d’indexer un ensemble de points vide</translation>
    </message>
    <message>
        <source>point sets must have 1 to 3 coordinates</source>
        <translation>les ensembles de points doivent avoir de 1 à 3 coordonnées</translation>
    </message>
    <message>
        <source>point set</source>
        <translation>ensemble de points</translation>
    </message>
    <message>
        <source>point sets of different dimensions</source>
        <translation>ensembles de points de dimensions différentes</translation>
    </message>
    <message>
        <source>too few points for box counting</source>
        <translation>trop peu de points pour le comptage de boîtes</translation>
    </message>
    <message>
        <source>all points coincide</source>
        <translation>tous les points sont confondus</translation>
    </message>
    <message>
        <source>not enough points for three box sizes with at least %1 points per box</source>
        <translation>pas assez de points pour trois tailles de boîtes avec au moins %1 points par boîte</translation>
    </message>
    <message>
        <source>the joint spectral radius needs at least one matrix</source>
        <translation>le rayon spectral joint demande au moins une matrice</translation>
    </message>
    <message>
        <source>the joint spectral radius needs square matrices of one size; matrix %1 differs</source>
        <translation>le rayon spectral joint demande des matrices carrées d’une même taille&#x202f;; la matrice %1 diffère</translation>
    </message>
    <message>
        <source>matrix %1</source>
        <translation>matrice %1</translation>
    </message>
    <message>
        <source>not convergent: the first difference scheme does not contract (JSR &gt;= 1)</source>
        <translation>non convergent&#xa0;: le premier schéma aux différences n’est pas contractant (JSR &gt;= 1)</translation>
    </message>
    <message>
        <source>convergence not certified within the time budget</source>
        <translation>convergence non certifiée dans le budget de temps imparti</translation>
    </message>
    <message>
        <source>C^%1, Hölder regularity in [%2, %3]</source>
        <translation>C^%1, régularité höldérienne dans [%2, %3]</translation>
    </message>
    <message>
        <source>cancelled; the bounds are those reached. </source>
        <translation>annulé&#x202f;; les bornes sont celles atteintes. </translation>
    </message>
    <message>
        <source>time budget spent; the bounds are those reached. </source>
        <translation>budget de temps épuisé&#x202f;; les bornes sont celles atteintes. </translation>
    </message>
    <message>
        <source>not convergent</source>
        <translation>non convergent</translation>
    </message>
    <message>
        <source>C^0 not certified</source>
        <translation>C^0 non certifiée</translation>
    </message>
    <message>
        <source>the arity of a scheme must be at least 2, got %1</source>
        <translation>l’arité d’un schéma doit être au moins 2 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the mask has a coefficient that is not a finite number</source>
        <translation>le masque a un coefficient qui n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>no difference scheme: the mask is zero</source>
        <translation>pas de schéma aux différences&#xa0;: le masque est nul</translation>
    </message>
    <message>
        <source>no difference scheme: the symbol a(z) has no factor 1 + z%1 (the rules&apos; weights do not each sum to 1), so the scheme does not reproduce constants and is not convergent</source>
        <translation>pas de schéma aux différences&#xa0;: le symbole a(z) n’a pas de facteur 1 + z%1 (la somme des poids de chaque règle ne vaut pas toujours 1), donc le schéma ne reproduit pas les constantes et n’est pas convergent</translation>
    </message>
    <message>
        <source>not convergent: the mask sums to %1, not the arity %2 (the scheme does not reproduce constants)</source>
        <translation>non convergent&#xa0;: la somme du masque vaut %1, et non l’arité %2 (le schéma ne reproduit pas les constantes)</translation>
    </message>
    <message>
        <source>the upper bound is the exact Hölder exponent only if the integer shifts of the basic limit function are stable (not checked for this mask). </source>
        <translation>la borne supérieure n’est l’exposant de Hölder exact que si les translatés entiers de la fonction limite fondamentale sont stables (non vérifié pour ce masque). </translation>
    </message>
    <message>
        <source>regularity needs at least two subdivision matrices</source>
        <translation>la régularité demande au moins deux matrices de subdivision</translation>
    </message>
    <message>
        <source>the subdivision matrices must all be square and of one size</source>
        <translation>les matrices de subdivision doivent toutes être carrées et de même taille</translation>
    </message>
    <message>
        <source>matrix S_%1</source>
        <translation>matrice S_%1</translation>
    </message>
    <message>
        <source>no difference scheme: the rows of S_%1 do not all sum to 1</source>
        <translation>pas de schéma aux différences&#xa0;: les lignes de S_%1 n’ont pas toutes pour somme 1</translation>
    </message>
    <message>
        <source>no regularity: S_1 or S_p has no simple eigenvalue 1, so the curve&apos;s end points are not defined</source>
        <translation>pas de régularité&#xa0;: S_1 ou S_p n’a pas de valeur propre 1 simple, donc les extrémités de la courbe ne sont pas définies</translation>
    </message>
    <message>
        <source>no regularity: the pieces S_%1 and S_%2 do not join (the attractor is not a continuous curve in its %3-adic parameter)</source>
        <translation>pas de régularité&#xa0;: les morceaux S_%1 et S_%2 ne se raccordent pas (l’attracteur n’est pas une courbe continue de son paramètre %3-adique)</translation>
    </message>
    <message>
        <source>C^infinity: the curve is one polynomial piece of degree %1</source>
        <translation>C^infinity&#xa0;: la courbe est un seul morceau polynomial de degré %1</translation>
    </message>
    <message>
        <source>the matrices reproduce every polynomial of degree &lt; %1 in the %2-adic parameter and leave no complement</source>
        <translation>les matrices reproduisent tout polynôme de degré &lt; %1 du paramètre %2-adique et ne laissent aucun complément</translation>
    </message>
    <message>
        <source>the upper bound assumes the curve&apos;s basis functions are stable. </source>
        <translation>la borne supérieure suppose que les fonctions de base de la courbe sont stables. </translation>
    </message>
    <message>
        <source>the pieces join only C^%1 (derivative %2 differs across a join). </source>
        <translation>les morceaux ne se raccordent qu’en C^%1 (la dérivée %2 diffère de part et d’autre d’un raccord). </translation>
    </message>
    <message>
        <source>C^infinity: a Bézier curve is a polynomial of degree %1</source>
        <translation>C^infinity&#xa0;: une courbe de Bézier est un polynôme de degré %1</translation>
    </message>
    <message>
        <source>de Casteljau subdivision reproduces the Bézier polynomial exactly</source>
        <translation>la subdivision de de Casteljau reproduit exactement le polynôme de Bézier</translation>
    </message>
    <message>
        <source>eigenvalues need a square matrix</source>
        <translation>les valeurs propres demandent une matrice carrée</translation>
    </message>
    <message>
        <source>matrix</source>
        <translation>matrice</translation>
    </message>
    <message>
        <source>the eigenvalue computation did not converge</source>
        <translation>le calcul des valeurs propres n’a pas convergé</translation>
    </message>
    <message>
        <source>no subdominant eigenvalue (the map is constant)</source>
        <translation>pas de valeur propre sous-dominante (l’application est constante)</translation>
    </message>
    <message>
        <source>real positive: the curve has a half-tangent at the fixed point, along the eigenvector (G1 where the two sides&apos; eigenvectors align)</source>
        <translation>réelle positive&#xa0;: la courbe a une demi-tangente au point fixe, dirigée par le vecteur propre (G1 là où les vecteurs propres des deux côtés sont alignés)</translation>
    </message>
    <message>
        <source>real positive but repeated: the tangent direction at the fixed point depends on the control points</source>
        <translation>réelle positive mais multiple&#xa0;: la direction de la tangente au point fixe dépend des points de contrôle</translation>
    </message>
    <message>
        <source>real negative: the curve oscillates at the fixed point and has no tangent there</source>
        <translation>réelle négative&#xa0;: la courbe oscille au point fixe et n’y a pas de tangente</translation>
    </message>
    <message>
        <source>complex pair: the curve spirals around the fixed point (no tangent)</source>
        <translation>paire complexe&#xa0;: la courbe s’enroule en spirale autour du point fixe (pas de tangente)</translation>
    </message>
    <message>
        <source>complex: near the fixed point the map acts as the spiral similarity z -&gt; lambda z, so the curve spirals around the fixed point (no tangent)</source>
        <translation>complexe&#xa0;: près du point fixe, l’application agit comme la similitude directe z -&gt; lambda z, donc la courbe s’enroule en spirale autour du point fixe (pas de tangente)</translation>
    </message>
    <message>
        <source>several eigenvalues of the same modulus with different signs or phases: no single tangent behaviour</source>
        <translation>plusieurs valeurs propres de même module avec des signes ou des phases différents&#xa0;: pas de comportement tangent unique</translation>
    </message>
    <message>
        <source>not contractive: spectral radius %1 &gt;= 1</source>
        <translation>non contractante&#xa0;: rayon spectral %1 &gt;= 1</translation>
    </message>
    <message>
        <source>contractive (factor ||A||_2 = %1)</source>
        <translation>contractante (facteur ||A||_2 = %1)</translation>
    </message>
    <message>
        <source>eventually contractive (spectral radius %1 &lt; 1; ||A^%2||_2 &lt; 1)</source>
        <translation>contractante à terme (rayon spectral %1 &lt; 1&#x202f;; ||A^%2||_2 &lt; 1)</translation>
    </message>
    <message>
        <source>eventually contractive (spectral radius %1 &lt; 1)</source>
        <translation>contractante à terme (rayon spectral %1 &lt; 1)</translation>
    </message>
    <message>
        <source>map %1 is not contractive: the spectral radius of its linear part is %2 &gt;= 1, so the IFS has no attractor (the iteration does not converge)</source>
        <translation>l’application %1 n’est pas contractante&#xa0;: le rayon spectral de sa partie linéaire vaut %2 &gt;= 1, donc l’IFS n’a pas d’attracteur (l’itération ne converge pas)</translation>
    </message>
    <message>
        <source>too many points to index</source>
        <translation>trop de points à indexer</translation>
    </message>
    <message>
        <source>; but the IFS contracts on average (Lyapunov exponent %1 along the orbit): random iteration draws its attractor</source>
        <translation>&#x202f;; mais l’IFS est contractant en moyenne (exposant de Lyapounov %1 le long de l’orbite)&#xa0;: l’itération aléatoire trace son attracteur</translation>
    </message>
    <message>
        <source>a curve needs at least one piece</source>
        <translation>une courbe nécessite au moins un morceau</translation>
    </message>
    <message>
        <source>a Bézier piece needs 2 to 31 plane control points</source>
        <translation>un morceau de Bézier nécessite de 2 à 31 points de contrôle du plan</translation>
    </message>
    <message>
        <source>a Bézier piece</source>
        <translation>un morceau de Bézier</translation>
    </message>
    <message>
        <source>a Takagi image needs 2 to 31 control points</source>
        <translation>une image de Takagi nécessite de 2 à 31 points de contrôle</translation>
    </message>
    <message>
        <source>the control points</source>
        <translation>les points de contrôle</translation>
    </message>
    <message>
        <source>a Takagi image needs a finite |y| &lt;= 1</source>
        <translation>une image de Takagi nécessite un |y| &lt;= 1 fini</translation>
    </message>
    <message>
        <source>the Hausdorff bracket needs a nonempty set of plane points</source>
        <translation>l&apos;encadrement de Hausdorff nécessite un ensemble non vide de points du plan</translation>
    </message>
    <message>
        <source>the point set</source>
        <translation>l&apos;ensemble de points</translation>
    </message>
    <message>
        <source>the s.m.p. candidate&apos;s leading eigenvalue is complex (%1); the complex-polytope variant is not implemented</source>
        <translation>la valeur propre dominante du candidat s.m.p. est complexe (%1)&#xa0;; la variante à polytope complexe n&apos;est pas implémentée</translation>
    </message>
    <message>
        <source>the s.m.p. candidate&apos;s leading eigenvalue is not simple in modulus (not a dominant product)</source>
        <translation>la valeur propre dominante du candidat s.m.p. n&apos;est pas simple en module (ce n&apos;est pas un produit dominant)</translation>
    </message>
    <message>
        <source>no real leading eigenvector</source>
        <translation>pas de vecteur propre dominant réel</translation>
    </message>
    <message>
        <source>invariant polytope: cancelled</source>
        <translation>polytope invariant&#xa0;: annulé</translation>
    </message>
    <message>
        <source>invariant polytope did not close in the budget (%1 vertices)</source>
        <translation>le polytope invariant ne s&apos;est pas fermé dans le budget imparti (%1 sommets)</translation>
    </message>
    <message>
        <source>invariant polytope did not close within %1 vertices</source>
        <translation>le polytope invariant ne s&apos;est pas fermé en %1 sommets au plus</translation>
    </message>
    <message>
        <source>JSR = 0: the matrices are empty or zero</source>
        <translation>JSR = 0&#xa0;: les matrices sont vides ou nulles</translation>
    </message>
    <message>
        <source>every product up to length %1 has spectral radius 0: no s.m.p. candidate</source>
        <translation>tout produit de longueur au plus %1 a un rayon spectral nul&#xa0;: aucun candidat s.m.p.</translation>
    </message>
    <message>
        <source>the family is numerically nilpotent (every product of length L vanishes to rounding): JSR = 0, no s.m.p. to certify</source>
        <translation>la famille est numériquement nilpotente (tout produit de longueur L s&apos;annule aux arrondis près)&#xa0;: JSR = 0, aucun s.m.p. à certifier</translation>
    </message>
    <message>
        <source>the invariant polytope closed but its certificate failed the check: </source>
        <translation>le polytope invariant s&apos;est fermé mais son certificat a échoué à la vérification&#xa0;: </translation>
    </message>
    <message>
        <source>invariant polytope closed: JSR = rho(A_w)^(1/%1) for the s.m.p. w = (%2), %3 vertices</source>
        <translation>polytope invariant fermé&#xa0;: JSR = rho(A_w)^(1/%1) pour le s.m.p. w = (%2), %3 sommets</translation>
    </message>
    <message>
        <source>the invariant polytope&apos;s bracket contradicts the bounds; ignored</source>
        <translation>l&apos;encadrement du polytope invariant contredit les bornes&#xa0;; ignoré</translation>
    </message>
    <message>
        <source>the parameter range [%1, %2] must be finite with from &lt; to</source>
        <translation>l&apos;intervalle de paramètre [%1, %2] doit être fini avec from &lt; to</translation>
    </message>
    <message>
        <source>the smoothness k must be between 0 and 30, got %1</source>
        <translation>la régularité k doit être comprise entre 0 et 30 (valeur reçue&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the grid must have 2 to 10000 values, got %1</source>
        <translation>la grille doit compter de 2 à 10000 valeurs (valeur reçue&#xa0;: %1)</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the mask is zero</source>
        <translation>pas d&apos;exposant de Sobolev&#xa0;: le masque est nul</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the symbol has no sum rule (the rules&apos; weights do not each sum to 1), so the scheme does not converge</source>
        <translation>pas d&apos;exposant de Sobolev&#xa0;: le symbole n&apos;a pas de règle de somme (les poids des règles n&apos;ont pas chacun pour somme 1), le schéma ne converge donc pas</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the mask sums to %1, not the arity %2 (the refinement equation has no integrable solution with nonzero mean)</source>
        <translation>pas d&apos;exposant de Sobolev&#xa0;: la somme du masque vaut %1, et non l&apos;arité %2 (l&apos;équation de raffinement n&apos;a pas de solution intégrable de moyenne non nulle)</translation>
    </message>
    <message>
        <source>no positive Sobolev smoothness: rho = %1 &gt;= 1 (to rounding), so s_2 = %2 &lt;= 0: with stable shifts the basic limit function is in no H^s with s &gt; 0, if it is a function at all</source>
        <translation>pas de régularité de Sobolev positive&#xa0;: rho = %1 &gt;= 1 (aux arrondis près), donc s_2 = %2 &lt;= 0&#xa0;: avec des translatées stables, la fonction limite de base n&apos;appartient à aucun H^s avec s &gt; 0, si tant est que ce soit une fonction</translation>
    </message>
    <message>
        <source>Sobolev exponent s_2 = %1: in H^s for every s &lt; %1</source>
        <translation>exposant de Sobolev s_2 = %1&#xa0;: dans H^s pour tout s &lt; %1</translation>
    </message>
    <message>
        <source> (capped at the %1 sum rules; -log_N(rho) / 2 = %2)</source>
        <translation> (plafonné aux %1 règles de somme&#xa0;; -log_N(rho) / 2 = %2)</translation>
    </message>
    <message>
        <source>not analysed: the mask has %1 coefficients, the regularity analysis takes at most %2 for arity %3 (transition matrices up to 48 x 48)</source>
        <translation>non analysé&#xa0;: le masque a %1 coefficients, l&apos;analyse de régularité en accepte au plus %2 pour l&apos;arité %3 (matrices de transition jusqu&apos;à 48 x 48)</translation>
    </message>
    <message>
        <source>; exact by the invariant polytope algorithm (Guglielmi &amp; Protasov 2013): s.m.p. (%1), %2 vertices</source>
        <translation>; résultat exact par l’algorithme du polytope invariant (Guglielmi &amp; Protasov 2013)&#xa0;: s.m.p. (%1), %2&#xa0;sommets</translation>
    </message>
    <message>
        <source>JSR of %1 matrices %2 x %2</source>
        <translation>JSR de %1 matrices %2 x %2</translation>
    </message>
    <message>
        <source>: lower bound max rho(product)^(1/k) over all products up to length %1</source>
        <translation>: borne inférieure max rho(product)^(1/k) sur tous les produits de longueur au plus %1</translation>
    </message>
    <message>
        <source> and the branch&apos;s products up to length %1</source>
        <translation> et les produits du branchement jusqu’à la longueur %1</translation>
    </message>
    <message>
        <source>, upper bound by Gripenberg&apos;s branch and bound (1996) in the %1</source>
        <translation>, borne supérieure par la méthode de séparation et évaluation de Gripenberg (1996) dans la %1</translation>
    </message>
    <message>
        <source>, upper bound in the %1</source>
        <translation>, borne supérieure dans la %1</translation>
    </message>
    <message>
        <source> (equal to the lower bound)</source>
        <translation> (égale à la borne inférieure)</translation>
    </message>
    <message>
        <source>, %1 products</source>
        <translation>, %1&#xa0;produits</translation>
    </message>
    <message>
        <source>r = n - log_%1 rho_n with n = %2 (a(z) has the factor (%3)^%2), rho_n the joint spectral radius of the transition matrices of the divided-difference mask of order %2 (Daubechies &amp; Lagarias 1992, Rioul 1992); %4%5</source>
        <translation>r = n - log_%1 rho_n, où n = %2 (a(z) admet le facteur (%3)^%2) et rho_n est le rayon spectral joint des matrices de transition du masque des différences divisées d’ordre %2 (Daubechies &amp; Lagarias 1992, Rioul 1992)&#x202f;; %4%5</translation>
    </message>
    <message>
        <source>r = -log_%1 rho with rho the joint spectral radius of S_1..S_%1 on the quotient by the control vectors of the polynomials of degree &lt; %2 that they generate (Micchelli &amp; Prautzsch 1989); %3%4</source>
        <translation>r = -log_%1 rho, où rho est le rayon spectral joint de S_1..S_%1 sur le quotient par les vecteurs de contrôle qui engendrent les polynômes de degré &lt; %2 (Micchelli &amp; Prautzsch 1989)&#x202f;; %3%4</translation>
    </message>
    <message>
        <source>s_2 = -log_%1(rho) / 2 with rho the spectral radius of the transition operator (T v)_i = sum_j b_{%1i - j} v_j of the autocorrelation b_k = (1/%1) sum_j a_j a_{j+k} on [-%2, %2], restricted to the %3-dimensional invariant subspace orthogonal to the polynomials of degree &lt; %4 (Eirola 1992, Villemoes 1994, Jia 1999); exact for stable integer shifts, a lower bound otherwise (Ron &amp; Shen 2000); rounding margin %5</source>
        <translation>s_2 = -log_%1(rho) / 2, où rho est le rayon spectral de l’opérateur de transition (T v)_i = sum_j b_{%1i - j} v_j de l’autocorrélation b_k = (1/%1) sum_j a_j a_{j+k} sur [-%2, %2], restreint au sous-espace invariant de dimension %3 orthogonal aux polynômes de degré &lt; %4 (Eirola 1992, Villemoes 1994, Jia 1999)&#x202f;; exact pour des translatés entiers stables, borne inférieure sinon (Ron &amp; Shen 2000)&#x202f;; marge d’arrondi %5</translation>
    </message>
    <message>
        <source>work budget spent; the bounds are those reached. </source>
        <translation>budget de calcul épuisé ; les bornes sont celles atteintes. </translation>
    </message>
    <message>
        <source>an atlas has one or two parameters, got %1</source>
        <translation>un atlas a un ou deux paramètres ; obtenu : %1</translation>
    </message>
    <message>
        <source>a parameter of the atlas has no name</source>
        <translation>un paramètre de l&apos;atlas n&apos;a pas de nom</translation>
    </message>
    <message>
        <source>the range of %1, [%2, %3], must be finite with from &lt; to</source>
        <translation>la plage de %1, [%2, %3], doit être finie avec « de » &lt; « à »</translation>
    </message>
    <message>
        <source>the grid of %1 must have 2 to %2 values, got %3</source>
        <translation>la grille de %1 doit avoir de 2 à %2 valeurs ; obtenu : %3</translation>
    </message>
    <message>
        <source>the two parameters of the atlas have the same name %1</source>
        <translation>les deux paramètres de l&apos;atlas portent le même nom %1</translation>
    </message>
    <message>
        <source>the tolerance must be a positive number</source>
        <translation>la tolérance doit être un nombre positif</translation>
    </message>
    <message>
        <source>the sections per round must be 1 to 64</source>
        <translation>le nombre de sections par tour doit être compris entre 1 et 64</translation>
    </message>
    <message>
        <source>the rounds must be 0 to 64</source>
        <translation>le nombre de tours doit être compris entre 0 et 64</translation>
    </message>
    <message>
        <source>the refinement levels must be 0 to 10, got %1</source>
        <translation>le nombre de niveaux de raffinement doit être compris entre 0 et 10 ; obtenu : %1</translation>
    </message>
    <message>
        <source>the work per point must be 1000 to 1e11 products</source>
        <translation>le travail par point doit être compris entre 1000 et 1e11 produits</translation>
    </message>
    <message>
        <source>the polytope vertices must be 0 to 100000</source>
        <translation>le nombre de sommets du polytope doit être compris entre 0 et 100000</translation>
    </message>
    <message>
        <source>the safety time must be 0 to 86400 s</source>
        <translation>le temps de sécurité doit être compris entre 0 et 86400 s</translation>
    </message>
    <message>
        <source>a grid of %1 x %2 points is more than the atlas&apos;s 1e6</source>
        <translation>une grille de %1 x %2 points dépasse le maximum de l&apos;atlas (1e6)</translation>
    </message>
    <message>
        <source>the atlas&apos;s previous batch has no rows yet</source>
        <translation>le lot précédent de l&apos;atlas n&apos;a encore aucune ligne</translation>
    </message>
    <message>
        <source>the atlas expected %1 rows, got %2</source>
        <translation>l&apos;atlas attendait %1 lignes ; obtenu : %2</translation>
    </message>
    <message>
        <source>a row of the atlas does not belong to its batch</source>
        <translation>une ligne de l&apos;atlas n&apos;appartient pas à son lot</translation>
    </message>
    <message>
        <source>map %1 is not contractive: its map of the plane has spectral radius %2 &gt;= 1 (%3 in the lifted space of its control points), so the IFS has no attractor (the iteration does not converge)</source>
        <translation>l&apos;application %1 n&apos;est pas contractante : son application du plan a un rayon spectral %2 &gt;= 1 (%3 dans l&apos;espace relevé de ses points de contrôle), donc l&apos;IFS n&apos;a pas d&apos;attracteur (l&apos;itération ne converge pas)</translation>
    </message>
    <message>
        <source>map %1 is not contractive in the lifted space of its control points (spectral radius %3 &gt;= 1), although its map of the plane contracts (spectral radius %2): the lifted iteration does not converge</source>
        <translation>l&apos;application %1 n&apos;est pas contractante dans l&apos;espace relevé de ses points de contrôle (rayon spectral %3 &gt;= 1), bien que son application du plan soit contractante (rayon spectral %2) : l&apos;itération relevée ne converge pas</translation>
    </message>
</context>
<context>
    <name>awb::cli</name>
    <message>
        <source>Render the bundled paper figures to PNG files (one row of panels per figure: the start set, a few iterates of the Hutchinson operator, and the attractor, over the control polygon).</source>
        <translation>Rendre les figures des articles fournies dans des fichiers PNG (une rangée de panneaux par figure&#xa0;: l’ensemble initial, quelques itérés de l’opérateur de Hutchinson et l’attracteur, sur le polygone de contrôle).</translation>
    </message>
    <message>
        <source>Directory for the PNG files (created if missing).</source>
        <translation>Répertoire des fichiers PNG (créé s’il n’existe pas).</translation>
    </message>
    <message>
        <source>List the examples and exit.</source>
        <translation>Lister les exemples et quitter.</translation>
    </message>
    <message>
        <source>attractor-cli: cannot create directory %1</source>
        <translation>attractor-cli&#xa0;: impossible de créer le répertoire %1</translation>
    </message>
    <message>
        <source>attractor-cli: unknown command &apos;%1&apos;</source>
        <translation>attractor-cli&#xa0;: commande inconnue «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>expected %1 project file, got %2 arguments (see --help)</source>
        <translation>%1 fichier de projet attendu, %2 arguments reçus (voir --help)</translation>
    </message>
    <message>
        <source>no item named &apos;%1&apos; in %2</source>
        <translation>aucun élément nommé «&#xa0;%1&#xa0;» dans %2</translation>
    </message>
    <message>
        <source>the figure&apos;s project</source>
        <translation>le projet de la figure</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no attractor</source>
        <translation>l’élément «&#xa0;%1&#xa0;» (%2) n’a pas d’attracteur</translation>
    </message>
    <message>
        <source>%1 has no item with an attractor</source>
        <translation>%1 n’a aucun élément avec un attracteur</translation>
    </message>
    <message>
        <source>item &apos;%1&apos;: %2</source>
        <translation>élément «&#xa0;%1&#xa0;»&#xa0;: %2</translation>
    </message>
    <message>
        <source>--%1 must be a whole number from %2 to %3, got &apos;%4&apos;</source>
        <translation>--%1 doit être un entier de %2 à %3 (reçu&#xa0;: «&#xa0;%4&#xa0;»)</translation>
    </message>
    <message>
        <source>--%1 must be a number from %2 to %3, got &apos;%4&apos;</source>
        <translation>--%1 doit être un nombre de %2 à %3 (reçu&#xa0;: «&#xa0;%4&#xa0;»)</translation>
    </message>
    <message>
        <source>--start: &apos;%1&apos; is not a finite number</source>
        <translation type="vanished">--start&#xa0;: «&#xa0;%1&#xa0;» n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>--start must be point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;..., got &apos;%1&apos;</source>
        <translation type="vanished">--start doit être de la forme point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>--start %1 needs %2 coordinates (%3 per point), got %4</source>
        <translation type="vanished">--start %1 demande %2 coordonnées (%3 par point) (reçu&#xa0;: %4)</translation>
    </message>
    <message>
        <source>a multiple of %1</source>
        <translation type="vanished">un multiple de %1</translation>
    </message>
    <message>
        <source>depth %1 gives %2 points, more than --max-points %3</source>
        <translation>la profondeur %1 donne %2 points, soit plus que --max-points %3</translation>
    </message>
    <message>
        <source>Image size in pixels (default 900x700).</source>
        <translation>Taille de l’image en pixels (par défaut 900x700).</translation>
    </message>
    <message>
        <source>Deterministic iteration depth (default: the item&apos;s).</source>
        <translation>Profondeur d’itération déterministe (par défaut&#xa0;: celle de l’élément).</translation>
    </message>
    <message>
        <source>Random iteration with this many points (up to 1e12; memory stays that of the raster).</source>
        <translation>Itération aléatoire avec ce nombre de points (jusqu’à 1e12&#x202f;; la mémoire reste celle de la trame).</translation>
    </message>
    <message>
        <source>Raster tone: &apos;hits&apos; (every lit pixel opaque, the papers&apos; look) or &apos;density&apos; (log density of the invariant measure, gamma and vibrancy as flame renderers). Default: the item&apos;s style (auto: hits for deterministic, density for random iteration).</source>
        <translation>Rendu tonal de la trame&#xa0;: «&#xa0;hits&#xa0;» (tout pixel touché est opaque, l’aspect des articles) ou «&#xa0;density&#xa0;» (densité logarithmique de la mesure invariante, gamma et vibrance comme dans les moteurs de rendu de flammes fractales). Par défaut&#xa0;: le style de l’élément (auto&#xa0;: hits pour l’itération déterministe, density pour l’itération aléatoire).</translation>
    </message>
    <message>
        <source>Density tone: display gamma (default: the item&apos;s, 2.2).</source>
        <translation>Rendu «&#xa0;density&#xa0;»&#xa0;: gamma d’affichage (par défaut&#xa0;: celui de l’élément, 2.2).</translation>
    </message>
    <message>
        <source>Density tone: 1 saturated colours, 0 per-channel gamma (default 1).</source>
        <translation>Rendu «&#xa0;density&#xa0;»&#xa0;: 1 pour des couleurs saturées, 0 pour un gamma par canal (par défaut 1).</translation>
    </message>
    <message>
        <source>Histogram cells per pixel side, 1..4 (default 1; 2 or 3 anti-alias edges).</source>
        <translation>Cellules d’histogramme par côté de pixel, 1..4 (par défaut 1&#x202f;; 2 ou 3 lissent les bords).</translation>
    </message>
    <message>
        <source>Threads of the raster engine (default: all cores).</source>
        <translation>Threads du moteur de rastérisation (par défaut&#xa0;: tous les cœurs).</translation>
    </message>
    <message>
        <source>Surfaces: the camera&apos;s azimuth and elevation in degrees (orthographic; default: the item&apos;s camera).</source>
        <translation>Surfaces&#xa0;: azimut et élévation de la caméra en degrés (orthographique&#x202f;; par défaut&#xa0;: la caméra de l’élément).</translation>
    </message>
    <message>
        <source>Plane figures: the world rectangle to frame (padded by 6%), e.g. to compare figures at one scale (default: fit the content).</source>
        <translation>Figures planes&#xa0;: le rectangle du monde à cadrer (avec une marge de 6&#xa0;%), par exemple pour comparer des figures à la même échelle (par défaut&#xa0;: ajuster au contenu).</translation>
    </message>
    <message>
        <source>The output&apos;s format when its name has no suffix (e.g. /dev/stdout): png, svg or pdf (default: the suffix).</source>
        <translation type="vanished">Format de la sortie lorsque son nom n’a pas de suffixe (p. ex. /dev/stdout)&#xa0;: png, svg ou pdf (par défaut&#xa0;: le suffixe).</translation>
    </message>
    <message>
        <source>--depth and --samples exclude each other</source>
        <translation>--depth et --samples s’excluent mutuellement</translation>
    </message>
    <message>
        <source>--size must be WxH with 64..16384 pixels each, got &apos;%1&apos;</source>
        <translation>--size doit être de la forme LxH avec 64..16384 pixels chacun (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>--tone must be &apos;hits&apos; or &apos;density&apos;, got &apos;%1&apos;</source>
        <translation>--tone doit valoir «&#xa0;hits&#xa0;» ou «&#xa0;density&#xa0;» (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>--bounds must be x0,y0,x1,y1 with x0 &lt; x1 and y0 &lt; y1, got &apos;%1&apos;</source>
        <translation>--bounds doit être de la forme x0,y0,x1,y1 avec x0 &lt; x1 et y0 &lt; y1 (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>--format must be png, svg or pdf, got &apos;%1&apos;</source>
        <translation type="vanished">--format doit valoir png, svg ou pdf (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>depth %1 makes %2 images; at most 4e9 are rendered</source>
        <translation type="vanished">la profondeur %1 produit %2 images&#x202f;; 4e9 au plus sont rendues</translation>
    </message>
    <message>
        <source>--view must be AZ,EL in degrees with |EL| &lt;= 90, got &apos;%1&apos;</source>
        <translation>--view doit être de la forme AZ,EL en degrés avec |EL| &lt;= 90 (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>%1 random points</source>
        <translation type="vanished">%1 points aléatoires</translation>
    </message>
    <message>
        <source>F^%1(X0)</source>
        <translation type="vanished">F^%1(X0)</translation>
    </message>
    <message>
        <source>, maps %1 of %2</source>
        <translation type="vanished">, applications %1 sur %2</translation>
    </message>
    <message>
        <source>%1: %2%3 — orthographic view from azimuth %4°, elevation %5°</source>
        <translation type="vanished">%1&#xa0;: %2%3 — vue orthographique depuis l’azimut %4°, élévation %5°</translation>
    </message>
    <message>
        <source>%1: %2 random points</source>
        <translation type="vanished">%1&#xa0;: %2 points aléatoires</translation>
    </message>
    <message>
        <source>%1: F^%2(X0)</source>
        <translation type="vanished">%1&#xa0;: F^%2(X0)</translation>
    </message>
    <message>
        <source>%1: polygon after %2 steps</source>
        <translation type="vanished">%1&#xa0;: polygone après %2 étapes</translation>
    </message>
    <message>
        <source>Render an item&apos;s attractor (with its control polygons) to PNG, SVG or PDF.</source>
        <translation type="vanished">Rendre l’attracteur d’un élément (avec ses polygones de contrôle) en PNG, SVG ou PDF.</translation>
    </message>
    <message>
        <source>The .awb project file.</source>
        <translation>Le fichier de projet .awb.</translation>
    </message>
    <message>
        <source>The item to render (default: the first with an attractor).</source>
        <translation>L’élément à rendre (par défaut&#xa0;: le premier qui a un attracteur).</translation>
    </message>
    <message>
        <source>Output file: .png, .svg or .pdf.</source>
        <translation type="vanished">Fichier de sortie&#xa0;: .png, .svg ou .pdf.</translation>
    </message>
    <message>
        <source>--out FILE is required</source>
        <translation>--out FICHIER est obligatoire</translation>
    </message>
    <message>
        <source>Render the frames of an item&apos;s animation (its keyframed parameters): numbered PNG files in a folder, or an MP4 or GIF movie through ffmpeg. Frame k is the item with its parameters at time k / fps, drawn exactly as `render` draws it.</source>
        <translation>Rendre les images de l’animation d’un élément (ses paramètres à clés)&#xa0;: des fichiers PNG numérotés dans un dossier, ou un film MP4 ou GIF via ffmpeg. L’image k est l’élément avec ses paramètres au temps k / fps, tracé exactement comme `render` le trace.</translation>
    </message>
    <message>
        <source>The animated item (default: the first item with an animation).</source>
        <translation>L’élément animé (par défaut&#xa0;: le premier élément qui a une animation).</translation>
    </message>
    <message>
        <source>A folder for frame-0000.png, frame-0001.png, ... (made if missing), a movie .mp4 or .gif (made by ffmpeg), or with --frame one .png/.svg/.pdf.</source>
        <translation>Un dossier pour frame-0000.png, frame-0001.png, ... (créé s’il n’existe pas), un film .mp4 ou .gif (produit par ffmpeg), ou, avec --frame, un seul fichier .png/.svg/.pdf.</translation>
    </message>
    <message>
        <source>Frames per second (default: the animation&apos;s).</source>
        <translation>Images par seconde (par défaut&#xa0;: celles de l’animation).</translation>
    </message>
    <message>
        <source>Render only frame K (0 = the start) to the file --out.</source>
        <translation>Rendre seulement l’image K (0 = le début) dans le fichier --out.</translation>
    </message>
    <message>
        <source>Captions without the frame&apos;s time and values.</source>
        <translation>Légendes sans le temps ni les valeurs de l’image.</translation>
    </message>
    <message>
        <source>--out DIR|FILE is required</source>
        <translation>--out DOSSIER|FICHIER est obligatoire</translation>
    </message>
    <message>
        <source>%1 has no animated item</source>
        <translation>%1 n’a aucun élément animé</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; has no animation: key its parameters in the Animation dock, or give it an &quot;animation&quot; field (docs/file-format.md)</source>
        <translation>l’élément «&#xa0;%1&#xa0;» n’a pas d’animation&#xa0;: posez des clés sur ses paramètres dans le panneau Animation, ou donnez-lui un champ &quot;animation&quot; (docs/file-format.md)</translation>
    </message>
    <message>
        <source>attractor-cli: note: the track of %1 is skipped: item &apos;%2&apos; has no such input now</source>
        <translation>attractor-cli&#xa0;: note&#xa0;: la piste de %1 est ignorée&#xa0;: l’élément «&#xa0;%2&#xa0;» n’a plus cette entrée</translation>
    </message>
    <message>
        <source>%1,%2,%3,%4</source>
        <translation>%1,%2,%3,%4</translation>
    </message>
    <message>
        <source>fitted per frame</source>
        <translation>ajusté à chaque image</translation>
    </message>
    <message>
        <source>frame %1 (t = %2 s): %3</source>
        <translation>image %1 (t = %2 s)&#xa0;: %3</translation>
    </message>
    <message>
        <source>writing %1 needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg); give --out a folder to get the frames as PNG files</source>
        <translation>l’écriture de %1 demande ffmpeg, qui n’est pas installé (Debian&#xa0;: apt-get install ffmpeg)&#x202f;; donnez un dossier à --out pour obtenir les images en fichiers PNG</translation>
    </message>
    <message>
        <source>cannot make a temporary folder for the frames: %1</source>
        <translation>impossible de créer un dossier temporaire pour les images&#xa0;: %1</translation>
    </message>
    <message>
        <source>%1 is a file, not a folder (a movie needs .mp4 or .gif)</source>
        <translation>%1 est un fichier, pas un dossier (un film demande .mp4 ou .gif)</translation>
    </message>
    <message>
        <source>cannot make the folder %1</source>
        <translation>impossible de créer le dossier %1</translation>
    </message>
    <message>
        <source>frame-%1.png</source>
        <translation>frame-%1.png</translation>
    </message>
    <message>
        <source>ffmpeg could not write %1: %2</source>
        <translation>ffmpeg n’a pas pu écrire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>%1: %2 frames of %3x%4 at %5 frames/s (%6 s); rendered in %7 s, %8 frames/s
bounds: %9
</source>
        <translation>%1&#xa0;: %2 images de %3x%4 à %5 images/s (%6 s)&#x202f;; rendu en %7 s, %8 images/s
limites&#xa0;: %9
</translation>
    </message>
    <message>
        <source>Analyse the items of a project: per map S_i (exact fractions), M_i = P^-1 S_i P with its blocks A_i, b_i, the eigenvalues of S_i and A_i, spectral radius, contractivity and fixed point; per item the subdominant eigenvalues, the Hausdorff distance to the exact curve and the box-counting dimension; per subdivision curve the certified Hölder regularity of its scheme.</source>
        <translation>Analyser les éléments d’un projet&#xa0;: pour chaque application, S_i (fractions exactes), M_i = P^-1 S_i P avec ses blocs A_i, b_i, les valeurs propres de S_i et de A_i, le rayon spectral, la contractivité et le point fixe&#x202f;; pour chaque élément, les valeurs propres sous-dominantes, la distance de Hausdorff à la courbe exacte et la dimension de comptage de boîtes&#x202f;; pour chaque courbe de subdivision, la régularité höldérienne certifiée de son schéma.</translation>
    </message>
    <message>
        <source>Only this item.</source>
        <translation>Seulement cet élément.</translation>
    </message>
    <message>
        <source>Print JSON (the only format so far).</source>
        <translation>Produire du JSON (le seul format pour l’instant).</translation>
    </message>
    <message>
        <source>--json is required (the only output format)</source>
        <translation>--json est obligatoire (le seul format de sortie)</translation>
    </message>
    <message>
        <source>Print the points of F^k(X0) as CSV: x, y (and z for a surface), the map applied last (1-based), and the view. --address w limits them to the sub-copy f_w(A): the points f_w(F^k(X0)).</source>
        <translation>Afficher les points de F^k(X0) en CSV&#xa0;: x, y (et z pour une surface), l’application appliquée en dernier (numérotée à partir de 1) et la vue. --address w les restreint à la sous-copie f_w(A)&#xa0;: les points f_w(F^k(X0)).</translation>
    </message>
    <message>
        <source>The item.</source>
        <translation type="vanished">L’élément.</translation>
    </message>
    <message>
        <source>Iteration depth (default: the item&apos;s).</source>
        <translation>Profondeur d’itération (par défaut&#xa0;: celle de l’élément).</translation>
    </message>
    <message>
        <source>Print CSV (the only format so far).</source>
        <translation>Produire du CSV (le seul format pour l’instant).</translation>
    </message>
    <message>
        <source>Only the sub-copy f_w(A) of this address: 0-based map numbers, w_1 (the outermost map) first, e.g. 0,1,1.</source>
        <translation>Seulement la sous-copie f_w(A) de cette adresse&#xa0;: numéros d’application à partir de 0, w_1 (l’application la plus extérieure) en premier, p. ex. 0,1,1.</translation>
    </message>
    <message>
        <source>Refuse to print more (default 10000000).</source>
        <translation>Refuser d’en afficher davantage (par défaut 10000000).</translation>
    </message>
    <message>
        <source>--item NAME is required</source>
        <translation type="vanished">--item NOM est obligatoire</translation>
    </message>
    <message>
        <source>--csv is required (the only output format)</source>
        <translation>--csv est obligatoire (le seul format de sortie)</translation>
    </message>
    <message>
        <source>--address %1: %2</source>
        <translation>--address %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>--start lifted: needs at least one point</source>
        <translation type="vanished">--start lifted&#xa0;: il faut au moins un point</translation>
    </message>
    <message>
        <source>cannot write to the standard output</source>
        <translation>impossible d’écrire sur la sortie standard</translation>
    </message>
    <message>
        <source>Validate a project file: it must load, and every item&apos;s IFS must be computable (exit 1: the file is refused; exit 3: it loads but items cannot be computed).</source>
        <translation>Valider un fichier de projet&#xa0;: il doit se charger, et l’IFS de chaque élément doit être calculable (code de sortie 1&#xa0;: le fichier est refusé&#x202f;; code de sortie 3&#xa0;: il se charge mais des éléments ne peuvent pas être calculés).</translation>
    </message>
    <message>
        <source>%1: %2: note: %3</source>
        <translation>%1&#xa0;: %2&#xa0;: note&#xa0;: %3</translation>
    </message>
    <message>
        <source>Load a project and save it again in the canonical form of this version (sorted keys, every field written): to upgrade or normalise a hand-written file.</source>
        <translation>Charger un projet et le réenregistrer sous la forme canonique de cette version (clés triées, tous les champs écrits)&#xa0;: pour mettre à niveau ou normaliser un fichier écrit à la main.</translation>
    </message>
    <message>
        <source>Write here instead of over the input.</source>
        <translation>Écrire ici au lieu d’écraser le fichier d’entrée.</translation>
    </message>
    <message>
        <source>v %1 %2 %3
</source>
        <translation>v %1 %2 %3
</translation>
    </message>
    <message>
        <source>ply (attractor points) or obj (subdivided mesh).</source>
        <translation type="vanished">ply (points de l’attracteur) ou obj (maillage subdivisé).</translation>
    </message>
    <message>
        <source>Output file.</source>
        <translation>Fichier de sortie.</translation>
    </message>
    <message>
        <source>PLY: iteration depth (default: the item&apos;s).</source>
        <translation>PLY&#xa0;: profondeur d’itération (par défaut&#xa0;: celle de l’élément).</translation>
    </message>
    <message>
        <source>PLY: refuse to write more (default 50000000).</source>
        <translation>PLY&#xa0;: refuser d’en écrire davantage (par défaut 50000000).</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj and --out FILE are required</source>
        <translation type="vanished">--item NOM, --format ply|obj et --out FICHIER sont obligatoires</translation>
    </message>
    <message>
        <source>--format must be ply or obj, got &apos;%1&apos;</source>
        <translation type="vanished">--format doit valoir ply ou obj (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>impossible d’écrire %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>OBJ export writes the subdivided net of a surface item; &apos;%1&apos; is a %2</source>
        <translation>l’export OBJ écrit le réseau subdivisé d’un élément surface&#x202f;; «&#xa0;%1&#xa0;» est de type %2</translation>
    </message>
    <message>
        <source>Print the control polygon after K subdivision steps as JSON {&quot;closed&quot;, &quot;points&quot;}: the figures of 001 for a normal-vector item (eq. (1) applied K times), classic subdivision S_w P for a subdivision curve.</source>
        <translation>Afficher le polygone de contrôle après K étapes de subdivision en JSON {&quot;closed&quot;, &quot;points&quot;}&#xa0;: les figures de 001 pour un élément à vecteurs normaux (éq. (1) appliquée K fois), la subdivision classique S_w P pour une courbe de subdivision.</translation>
    </message>
    <message>
        <source>Subdivision steps K (0: the control polygon).</source>
        <translation>Étapes de subdivision K (0&#xa0;: le polygone de contrôle).</translation>
    </message>
    <message>
        <source>Print JSON (the only format).</source>
        <translation>Produire du JSON (le seul format).</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; has a complex split parameter: its control polygon has complex points</source>
        <translation>l’élément «&#xa0;%1&#xa0;» a un paramètre de découpe complexe&#xa0;: son polygone de contrôle a des points complexes</translation>
    </message>
    <message>
        <source>level %1 gives more than 5e7 points</source>
        <translation>le niveau %1 donne plus de 5e7 points</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) is not polygon-based: the polygon command takes normal-vector items and subdivision curves</source>
        <translation>l’élément «&#xa0;%1&#xa0;» (%2) n’est pas fondé sur un polygone&#xa0;: la commande polygon accepte les éléments à vecteurs normaux et les courbes de subdivision</translation>
    </message>
    <message>
        <source>nothing to draw</source>
        <translation>rien à dessiner</translation>
    </message>
    <message>
        <source>Make a project of a mesh file (OBJ, OFF, PLY ASCII or binary): one subdivision-mesh item with the file&apos;s vertices, in its numbering, and its polygons.</source>
        <translation type="vanished">Créer un projet à partir d’un fichier de maillage (OBJ, OFF, PLY ASCII ou binaire)&#xa0;: un élément subdivision-mesh avec les sommets du fichier, dans sa numérotation, et ses polygones.</translation>
    </message>
    <message>
        <source>The mesh file.</source>
        <translation>Le fichier de maillage.</translation>
    </message>
    <message>
        <source>catmull-clark (any polygons, the default) or loop (triangles).</source>
        <translation>catmull-clark (polygones quelconques, par défaut) ou loop (triangles).</translation>
    </message>
    <message>
        <source>The project file to write (.awb).</source>
        <translation>Le fichier de projet à écrire (.awb).</translation>
    </message>
    <message>
        <source>The item&apos;s name (default: the file&apos;s base name).</source>
        <translation>Le nom de l’élément (par défaut&#xa0;: le nom du fichier sans son extension).</translation>
    </message>
    <message>
        <source>--scheme must be catmull-clark or loop, got &apos;%1&apos;</source>
        <translation>--scheme doit valoir catmull-clark ou loop (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be an item&apos;s name</source>
        <translation>«&#xa0;%1&#xa0;» ne peut pas être le nom d’un élément</translation>
    </message>
    <message>
        <source>%1: item &apos;%2&apos;, %3 vertices, %4 faces, %5 extraordinary vertices (%6)
</source>
        <translation>%1&#xa0;: élément «&#xa0;%2&#xa0;», %3 sommets, %4 faces, %5 sommets extraordinaires (%6)
</translation>
    </message>
    <message>
        <source>attractor-cli: note: %1</source>
        <translation type="vanished">attractor-cli&#xa0;: note&#xa0;: %1</translation>
    </message>
    <message>
        <source>Start set: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (plane coordinates; x,y,z for a surface) | lifted:x,y,c1,...;x,y,c1,... (points of the lifted space of 000 §2) | vertex-limits (a mesh item: the limit positions of the vertices of the mesh refined k times; default: the item&apos;s).</source>
        <translation type="vanished">Ensemble initial&#xa0;: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (coordonnées du plan&#x202f;; x,y,z pour une surface) | lifted:x,y,c1,...;x,y,c1,... (points de l’espace relevé de 000 §2) | vertex-limits (élément maillage&#xa0;: les positions limites des sommets du maillage raffiné k fois&#x202f;; par défaut&#xa0;: celui de l’élément).</translation>
    </message>
    <message>
        <source>--start vertex-limits needs a mesh item; &apos;%1&apos; is a %2</source>
        <translation type="vanished">--start vertex-limits demande un élément maillage&#x202f;; «&#xa0;%1&#xa0;» est de type %2</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ).</source>
        <translation type="vanished">Exporter la géométrie d’un élément&#xa0;: l’attracteur F^k(X0) en nuage de points PLY (avec l’application appliquée en dernier pour chaque point), le réseau d’un élément surface après k passes de subdivision classique en maillage OBJ, ou un élément maillage après k étapes avec chaque sommet à sa position limite (OBJ).</translation>
    </message>
    <message>
        <source>OBJ: rounds of subdivision (default: the item&apos;s; a mesh item: its depth, at most 6).</source>
        <translation>OBJ&#xa0;: passes de subdivision (par défaut&#xa0;: celles de l’élément&#x202f;; pour un élément maillage&#xa0;: sa profondeur, au plus 6).</translation>
    </message>
    <message>
        <source>%1 steps give %2 vertices: too many</source>
        <translation type="vanished">%1 étapes donnent %2 sommets&#xa0;: c’est trop</translation>
    </message>
    <message>
        <source>Attractor Workbench: item %1, %2 after %3 steps, every vertex at its limit position</source>
        <translation type="vanished">Attractor Workbench&#xa0;: élément %1, %2 après %3 étapes, chaque sommet à sa position limite</translation>
    </message>
    <message>
        <source>Usage: attractor-cli &lt;command&gt; [options]

Commands:
  render     render an item of a project to PNG, SVG or PDF
  animate    render the frames of an item&apos;s animation (PNG files, MP4/GIF)
  analyse    eigenvalues, contractivity, fixed points, dimension (JSON)
  points     the points of F^k(X0) as CSV
  check      validate a project file
  rewrite    load and save a project in canonical form
  export     attractor points as PLY, a subdivided net or mesh (limit) as OBJ
  polygon    the control polygon after K subdivision steps (JSON)
  import-mesh  a mesh file (OBJ, OFF, PLY) as a project with a mesh item
  examples   render the built-in paper figures (000 Figs. 2, 3, 5) to PNG

Run &apos;attractor-cli &lt;command&gt; --help&apos; for the options of a command.
</source>
        <translation type="vanished">Utilisation&#xa0;: attractor-cli &lt;commande&gt; [options]

Commandes&#xa0;:
  render     rendre un élément d’un projet en PNG, SVG ou PDF
  animate    rendre les images de l’animation d’un élément (fichiers PNG, MP4/GIF)
  analyse    valeurs propres, contractivité, points fixes, dimension (JSON)
  points     les points de F^k(X0) en CSV
  check      valider un fichier de projet
  rewrite    charger et réenregistrer un projet sous forme canonique
  export     points de l’attracteur en PLY, réseau subdivisé ou maillage (à la limite) en OBJ
  polygon    le polygone de contrôle après K étapes de subdivision (JSON)
  import-mesh  un fichier de maillage (OBJ, OFF, PLY) en projet avec un élément maillage
  examples   rendre les figures des articles intégrées (000 fig. 2, 3, 5) en PNG

Lancez «&#xa0;attractor-cli &lt;commande&gt; --help&#xa0;» pour connaître les options d’une commande.
</translation>
    </message>
    <message>
        <source>--out FILE (the project to write) is required</source>
        <translation>--out FILE (le projet à écrire) est obligatoire</translation>
    </message>
    <message>
        <source>The spectrum of the local subdivision matrix at an interior vertex of each valence: lambda (with its closed form), mu, lambda^2, Reif&apos;s C1 verdict and the curvature.</source>
        <translation>Le spectre de la matrice de subdivision locale en un sommet intérieur de chaque valence&#xa0;: lambda (avec sa forme close), mu, lambda^2, le verdict C1 de Reif et la courbure.</translation>
    </message>
    <message>
        <source>catmull-clark (the default) or loop.</source>
        <translation>catmull-clark (par défaut) ou loop.</translation>
    </message>
    <message>
        <source>The smallest valence (3 to 64, default 3).</source>
        <translation>La plus petite valence (3 à 64, 3 par défaut).</translation>
    </message>
    <message>
        <source>The largest valence (3 to 64, default 16).</source>
        <translation>La plus grande valence (3 à 64, 16 par défaut).</translation>
    </message>
    <message>
        <source>Print JSON instead of a table.</source>
        <translation>Afficher du JSON au lieu d’un tableau.</translation>
    </message>
    <message>
        <source>Usage: attractor-cli &lt;command&gt; [options]

Commands:
  render     render an item of a project to PNG, SVG or PDF
  animate    render the frames of an item&apos;s animation (PNG files, MP4/GIF)
  analyse    eigenvalues, contractivity, fixed points, dimension (JSON)
  points     the points of F^k(X0) as CSV
  check      validate a project file
  rewrite    load and save a project in canonical form
  export     attractor points as PLY, a subdivided net or mesh (limit) as OBJ
  polygon    the control polygon after K subdivision steps (JSON)
  import-mesh  a mesh file (OBJ, OFF, PLY) as a project with a mesh item
  valences   lambda, mu, Reif&apos;s C1 verdict per valence (Catmull-Clark, Loop)
  examples   render the built-in paper figures (000 Figs. 2, 3, 5) to PNG

Run &apos;attractor-cli &lt;command&gt; --help&apos; for the options of a command.
</source>
        <translation type="vanished">Utilisation&#xa0;: attractor-cli &lt;commande&gt; [options]

Commandes&#xa0;:
  render     rendre un élément d’un projet en PNG, SVG ou PDF
  animate    rendre les images de l’animation d’un élément (fichiers PNG, MP4/GIF)
  analyse    valeurs propres, contractivité, points fixes, dimension (JSON)
  points     les points de F^k(X0) en CSV
  check      valider un fichier de projet
  rewrite    charger et réenregistrer un projet sous forme canonique
  export     points de l’attracteur en PLY, réseau subdivisé ou maillage (à la limite) en OBJ
  polygon    le polygone de contrôle après K étapes de subdivision (JSON)
  import-mesh  un fichier de maillage (OBJ, OFF, PLY) en projet avec un élément maillage
  valences   lambda, mu, verdict C1 de Reif par valence (Catmull-Clark, Loop)
  examples   rendre les figures des articles intégrées (000 fig. 2, 3, 5) en PNG

Lancez «&#xa0;attractor-cli &lt;commande&gt; --help&#xa0;» pour connaître les options d’une commande.
</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation type="vanished">Exporter la géométrie d’un élément&#xa0;: l’attracteur F^k(X0) en nuage de points PLY (avec l’application appliquée en dernier pour chaque point), le réseau d’un élément surface après k passes de subdivision classique en maillage OBJ, ou un élément maillage après k étapes avec chaque sommet à sa position limite (OBJ)&#x202f;; ou ses matrices S_i, M_i, A_i en tableaux de cellules MATLAB pour la JSR toolbox (matlab).</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh) or matlab (matrices).</source>
        <translation type="vanished">ply (points de l’attracteur), obj (maillage subdivisé) ou matlab (matrices).</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|matlab and --out FILE are required</source>
        <translation type="vanished">--item NAME, --format ply|obj|matlab et --out FILE sont obligatoires</translation>
    </message>
    <message>
        <source>--format must be ply, obj or matlab, got &apos;%1&apos;</source>
        <translation type="vanished">--format doit valoir ply, obj ou matlab, et non «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); its maps as a Fractint .ifs entry (ifs); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation type="vanished">Exporter la géométrie d’un élément&#xa0;: l’attracteur F^k(X0) en nuage de points PLY (avec l’application appliquée en dernier pour chaque point), le réseau d’un élément surface après k passes de subdivision classique en maillage OBJ, ou un élément maillage après k étapes avec chaque sommet à sa position limite (OBJ)&#x202f;; ses applications en entrée de fichier .ifs Fractint (ifs)&#x202f;; ou ses matrices S_i, M_i, A_i en tableaux de cellules MATLAB pour la JSR toolbox (matlab).</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh), ifs (Fractint) or matlab (matrices).</source>
        <translation type="vanished">ply (points de l’attracteur), obj (maillage subdivisé), ifs (Fractint) ou matlab (matrices).</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|ifs|matlab and --out FILE are required</source>
        <translation type="vanished">--item NAME, --format ply|obj|ifs|matlab et --out FILE sont obligatoires</translation>
    </message>
    <message>
        <source>--format must be ply, obj, ifs or matlab, got &apos;%1&apos;</source>
        <translation type="vanished">--format doit valoir ply, obj, ifs ou matlab (reçu&#xa0;: «&#xa0;%1&#xa0;»)</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit) as a fractal with control points.</source>
        <translation type="vanished">Créer un projet à partir du fichier IFS d’un autre outil&#xa0;: chaque entrée d’un fichier .ifs Fractint (2D et 3D, le format de Fractint, de xfractint et de l’IFS Construction Kit) devient une fractale à points de contrôle.</translation>
    </message>
    <message>
        <source>The file to import (.ifs).</source>
        <translation type="vanished">Le fichier à importer (.ifs).</translation>
    </message>
    <message>
        <source>%1: import reads Fractint .ifs files</source>
        <translation type="vanished">%1&#xa0;: la commande import lit les fichiers .ifs Fractint</translation>
    </message>
    <message>
        <source>%1: no entry could be imported</source>
        <translation>%1&#xa0;: aucune entrée n’a pu être importée</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n item(s): %2
</source>
        <translation>
            <numerusform>%1&#xa0;: %n élément&#xa0;: %2
</numerusform>
            <numerusform>%1&#xa0;: %n éléments&#xa0;: %2
</numerusform>
        </translation>
    </message>
    <message>
        <source>Usage: attractor-cli &lt;command&gt; [options]

Commands:
  render     render an item of a project to PNG, SVG or PDF
  animate    render the frames of an item&apos;s animation (PNG files, MP4/GIF)
  analyse    eigenvalues, contractivity, fixed points, dimension (JSON)
  points     the points of F^k(X0) as CSV
  check      validate a project file
  rewrite    load and save a project in canonical form
  export     points (PLY), a net or mesh (OBJ), maps (.ifs), matrices (MATLAB)
  polygon    the control polygon after K subdivision steps (JSON)
  import     another tool&apos;s IFS file (Fractint .ifs) as a project
  import-mesh  a mesh file (OBJ, OFF, PLY) as a project with a mesh item
  valences   lambda, mu, Reif&apos;s C1 verdict per valence (Catmull-Clark, Loop)
  examples   render the built-in paper figures (000 Figs. 2, 3, 5) to PNG

Run &apos;attractor-cli &lt;command&gt; --help&apos; for the options of a command.
</source>
        <translation type="vanished">Utilisation&#xa0;: attractor-cli &lt;commande&gt; [options]

Commandes&#xa0;:
  render     rendre un élément d’un projet en PNG, SVG ou PDF
  animate    rendre les images de l’animation d’un élément (fichiers PNG, MP4/GIF)
  analyse    valeurs propres, contractivité, points fixes, dimension (JSON)
  points     les points de F^k(X0) en CSV
  check      valider un fichier de projet
  rewrite    charger et réenregistrer un projet sous forme canonique
  export     points (PLY), réseau ou maillage (OBJ), applications (.ifs), matrices (MATLAB)
  polygon    le polygone de contrôle après K étapes de subdivision (JSON)
  import     un fichier IFS d’un autre outil (Fractint .ifs) en projet
  import-mesh  un fichier de maillage (OBJ, OFF, PLY) en projet avec un élément maillage
  valences   lambda, mu, verdict C1 de Reif par valence (Catmull-Clark, Loop)
  examples   rendre les figures des articles intégrées (000 fig. 2, 3, 5) en PNG

Lancez «&#xa0;attractor-cli &lt;commande&gt; --help&#xa0;» pour connaître les options d’une commande.
</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); its maps as a Fractint .ifs entry (ifs) or a flam3 genome that flam3-render draws in the frame of render&apos;s --size and --bounds (flame); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation>Exporter la géométrie d’un élément&#xa0;: l’attracteur F^k(X0) comme nuage de points PLY (avec, pour chaque point, l’application appliquée en dernier), le réseau d’un élément surface après k passes de subdivision classique comme maillage OBJ, ou un élément maillage après k étapes avec chaque sommet à sa position limite (OBJ)&#xa0;; ses applications comme entrée .ifs de Fractint (ifs) ou comme génome flam3 que flam3-render dessine dans le cadre des options --size et --bounds de render (flame)&#xa0;; ou ses matrices S_i, M_i, A_i comme tableaux de cellules MATLAB pour la boîte à outils JSR (matlab).</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh), ifs (Fractint), flame (flam3) or matlab (matrices).</source>
        <translation>ply (points de l’attracteur), obj (maillage subdivisé), ifs (Fractint), flame (flam3) ou matlab (matrices).</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|ifs|flame|matlab and --out FILE are required</source>
        <translation type="vanished">--item NOM, --format ply|obj|ifs|flame|matlab et --out FICHIER sont obligatoires</translation>
    </message>
    <message>
        <source>--format must be ply, obj, ifs, flame or matlab, got &apos;%1&apos;</source>
        <translation>--format doit valoir ply, obj, ifs, flame ou matlab, reçu «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has nothing to frame</source>
        <translation>«&#xa0;%1&#xa0;» n’a rien à cadrer</translation>
    </message>
    <message>
        <source>The output&apos;s format when its name has no suffix (e.g. /dev/stdout): png, svg, pdf or exr (default: the suffix).</source>
        <translation>Format de la sortie lorsque son nom n’a pas de suffixe (p. ex. /dev/stdout)&#xa0;: png, svg, pdf ou exr (par défaut&#xa0;: le suffixe).</translation>
    </message>
    <message>
        <source>PNG: 8 (the figure, default) or 16 (the attractor&apos;s raw density: alpha = log(1 + hits) / log(1 + most hits), the colour the hits&apos; mean; no title, polygons or margins). An .exr file always holds the raw density, as float32 counts.</source>
        <translation>PNG&#xa0;: 8 (la figure, par défaut) ou 16 (la densité brute de l’attracteur&#xa0;: alpha = log(1 + impacts) / log(1 + impacts max), la couleur étant la moyenne des impacts&#xa0;; ni titre, ni polygones, ni marges). Un fichier .exr contient toujours la densité brute, sous forme de comptes float32.</translation>
    </message>
    <message>
        <source>--format must be png, svg, pdf or exr, got &apos;%1&apos;</source>
        <translation>--format doit valoir png, svg, pdf ou exr, reçu «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>--bits must be 8 or 16, got &apos;%1&apos;</source>
        <translation>--bits doit valoir 8 ou 16, reçu «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>--bits 16 writes PNG files, got &apos;%1&apos;</source>
        <translation type="vanished">--bits 16 écrit des fichiers PNG, reçu «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>the raw density (.exr, --bits 16) counts an attractor&apos;s points; this item&apos;s figure is a polygon</source>
        <translation type="vanished">la densité brute (.exr, --bits 16) compte les points d’un attracteur&#xa0;; la figure de cet élément est un polygone</translation>
    </message>
    <message>
        <source>the raw density (.exr, --bits 16) is of attractors drawn in the plane; &apos;%1&apos; is drawn in space</source>
        <translation type="vanished">la densité brute (.exr, --bits 16) concerne les attracteurs dessinés dans le plan&#xa0;; «&#xa0;%1&#xa0;» est dessiné dans l’espace</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit), or every flame of a flam3 genome (.flame, .flam3: flam3, Apophysis, JWildfire), as a fractal with control points. Non-linear variations are dropped with a warning.</source>
        <translation type="vanished">Créer un projet à partir du fichier IFS d’un autre outil&#xa0;: chaque entrée d’un fichier .ifs de Fractint (2D et 3D, le format de Fractint, de xfractint et de l’IFS Construction Kit), ou chaque flamme d’un génome flam3 (.flame, .flam3&#xa0;: flam3, Apophysis, JWildfire), devient une fractale avec des points de contrôle. Les variations non linéaires sont abandonnées avec un avertissement.</translation>
    </message>
    <message>
        <source>The file to import (.ifs, .flame, .flam3).</source>
        <translation>Le fichier à importer (.ifs, .flame, .flam3).</translation>
    </message>
    <message>
        <source>%1: import reads Fractint .ifs and flam3 .flame (.flam3) files</source>
        <translation>%1&#xa0;: import lit les fichiers .ifs de Fractint et .flame (.flam3) de flam3</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>avertissement&#xa0;: %1</translation>
    </message>
    <message>
        <source>Render an item&apos;s attractor (with its control polygons) to PNG, SVG or PDF; or its raw density (hits per pixel) to OpenEXR (.exr, float32 counts) or a 16-bit PNG (--bits 16), to tone-map elsewhere.</source>
        <translation>Rendre l’attracteur d’un élément (avec ses polygones de contrôle) en PNG, SVG ou PDF&#xa0;; ou sa densité brute (impacts par pixel) en OpenEXR (.exr, comptes float32) ou en PNG 16 bits (--bits 16), pour un mappage tonal ailleurs.</translation>
    </message>
    <message>
        <source>Output file: .png, .svg, .pdf or .exr.</source>
        <translation>Fichier de sortie&#xa0;: .png, .svg, .pdf ou .exr.</translation>
    </message>
    <message>
        <source>With --item: write the certificate of the curve&apos;s exact Hölder exponent (verify-regularity checks it).</source>
        <translation>Avec --item&#xa0;: écrire le certificat de l&apos;exposant de Hölder exact de la courbe (verify-regularity le vérifie).</translation>
    </message>
    <message>
        <source>--certificate needs --item: the certificate is one curve&apos;s</source>
        <translation>--certificate nécessite --item&#xa0;: le certificat porte sur une seule courbe</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is not a subdivision curve: no regularity to certify</source>
        <translation>l&apos;élément &apos;%1&apos; n&apos;est pas une courbe de subdivision&#xa0;: aucune régularité à certifier</translation>
    </message>
    <message>
        <source>Where a curve scheme is C^k as one of its parameters moves: the parameter intervals on which the certified Hölder exponent exceeds k, each end bracketed by bisection on certified values.</source>
        <translation>Où un schéma de courbe est C^k lorsque l&apos;un de ses paramètres varie&#xa0;: les intervalles de paramètre sur lesquels l&apos;exposant de Hölder certifié dépasse k, chaque extrémité étant encadrée par dichotomie sur des valeurs certifiées.</translation>
    </message>
    <message>
        <source>The project file (.awb).</source>
        <translation>Le fichier de projet (.awb).</translation>
    </message>
    <message>
        <source>The curve item (default: the first item with an attractor).</source>
        <translation>L&apos;élément courbe (par défaut&#xa0;: le premier élément ayant un attracteur).</translation>
    </message>
    <message>
        <source>omega (four-point), a or b (corner cutting).</source>
        <translation type="vanished">omega (quatre points), a ou b (découpe des coins).</translation>
    </message>
    <message>
        <source>The start of the range.</source>
        <translation>Le début de l&apos;intervalle.</translation>
    </message>
    <message>
        <source>The end of the range.</source>
        <translation>La fin de l&apos;intervalle.</translation>
    </message>
    <message>
        <source>k: the class C^k asked for (default 1).</source>
        <translation>k&#xa0;: la classe C^k demandée (par défaut 1).</translation>
    </message>
    <message>
        <source>Values of the first sweep, 2 to 10000 (default 24).</source>
        <translation>Valeurs du premier balayage, de 2 à 10000 (par défaut 24).</translation>
    </message>
    <message>
        <source>Bracket width at which bisection stops (default 1e-6).</source>
        <translation>Largeur d&apos;encadrement à laquelle la dichotomie s&apos;arrête (par défaut 1e-6).</translation>
    </message>
    <message>
        <source>Seconds of joint spectral radius per value (default 0.3).</source>
        <translation>Secondes de calcul du rayon spectral joint par valeur (par défaut 0.3).</translation>
    </message>
    <message>
        <source>Print JSON instead of text.</source>
        <translation>Afficher du JSON au lieu de texte.</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is not a subdivision curve: its scheme has no parameter to move</source>
        <translation>l&apos;élément &apos;%1&apos; n&apos;est pas une courbe de subdivision&#xa0;: son schéma n&apos;a pas de paramètre à faire varier</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no parameter &apos;%3&apos;: omega belongs to the four-point scheme, a and b to corner cutting</source>
        <translation type="vanished">l&apos;élément &apos;%1&apos; (%2) n&apos;a pas de paramètre &apos;%3&apos;&#xa0;: omega appartient au schéma à quatre points, a et b à la découpe des coins</translation>
    </message>
    <message>
        <source>--from and --to are required</source>
        <translation>--from et --to sont obligatoires</translation>
    </message>
    <message>
        <source>%1: C^%2 for %3 in %4 interval(s) of [%5, %6]</source>
        <translation>%1&#xa0;: C^%2 pour %3 sur %4 intervalle(s) de [%5, %6]</translation>
    </message>
    <message>
        <source>%1 (the range&apos;s end)</source>
        <translation>%1 (l&apos;extrémité de l&apos;intervalle)</translation>
    </message>
    <message>
        <source>in [%1, %2]%3</source>
        <translation>dans [%1, %2]%3</translation>
    </message>
    <message>
        <source> (the bounds cannot decide beyond)</source>
        <translation> (les bornes ne permettent pas de trancher au-delà)</translation>
    </message>
    <message>
        <source>  from %1 to %2</source>
        <translation>  de %1 à %2</translation>
    </message>
    <message>
        <source>%1 evaluations, %2 s</source>
        <translation>%1 évaluations, %2 s</translation>
    </message>
    <message>
        <source>Re-check the certificate of an exact Hölder exponent, independently of the search that found it.</source>
        <translation>Revérifier le certificat d&apos;un exposant de Hölder exact, indépendamment de la recherche qui l&apos;a trouvé.</translation>
    </message>
    <message>
        <source>The certificate (.json).</source>
        <translation>Le certificat (.json).</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>%1: larger than 64 MiB, not a certificate</source>
        <translation>%1&#xa0;: plus de 64 Mio, ce n&apos;est pas un certificat</translation>
    </message>
    <message>
        <source>Usage: attractor-cli &lt;command&gt; [options]

Commands:
  render     render an item of a project to PNG, SVG or PDF
  animate    render the frames of an item&apos;s animation (PNG files, MP4/GIF)
  analyse    eigenvalues, contractivity, fixed points, dimension (JSON)
  points     the points of F^k(X0) as CSV
  check      validate a project file
  rewrite    load and save a project in canonical form
  export     points (PLY), a net or mesh (OBJ), maps (.ifs), matrices (MATLAB)
  polygon    the control polygon after K subdivision steps (JSON)
  import     another tool&apos;s IFS file (Fractint .ifs) as a project
  import-mesh  a mesh file (OBJ, OFF, PLY) as a project with a mesh item
  valences   lambda, mu, Reif&apos;s C1 verdict per valence (Catmull-Clark, Loop)
  regularity-interval  where a scheme is C^k as a parameter moves
  verify-regularity  re-check the certificate of an exact Hölder exponent
  examples   render the built-in paper figures (000 Figs. 2, 3, 5) to PNG

Run &apos;attractor-cli &lt;command&gt; --help&apos; for the options of a command.
</source>
        <translation type="vanished">Utilisation&#xa0;: attractor-cli &lt;commande&gt; [options]

Commandes&#xa0;:
  render     effectuer le rendu d&apos;un élément d&apos;un projet en PNG, SVG ou PDF
  animate    effectuer le rendu des images de l&apos;animation d&apos;un élément (fichiers PNG, MP4/GIF)
  analyse    valeurs propres, contractivité, points fixes, dimension (JSON)
  points     les points de F^k(X0) en CSV
  check      valider un fichier de projet
  rewrite    charger et enregistrer un projet sous forme canonique
  export     points (PLY), réseau ou maillage (OBJ), applications (.ifs), matrices (MATLAB)
  polygon    le polygone de contrôle après K étapes de subdivision (JSON)
  import     le fichier IFS d&apos;un autre outil (Fractint .ifs) comme projet
  import-mesh  un fichier de maillage (OBJ, OFF, PLY) comme projet avec un élément maillage
  valences   lambda, mu, verdict C1 de Reif par valence (Catmull-Clark, Loop)
  regularity-interval  où un schéma est C^k lorsqu&apos;un paramètre varie
  verify-regularity  revérifier le certificat d&apos;un exposant de Hölder exact
  examples   rendre en PNG les figures intégrées de l&apos;article (000, fig. 2, 3 et 5)

Exécutez &apos;attractor-cli &lt;commande&gt; --help&apos; pour les options d&apos;une commande.
</translation>
    </message>
    <message>
        <source>omega (four-point), a or b (corner cutting), or the name used in --mask.</source>
        <translation>omega (quatre points), a ou b (découpe des coins), ou le nom utilisé dans --mask.</translation>
    </message>
    <message>
        <source>For a mask item: its coefficients with the parameter in them, e.g. &quot;-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w&quot;.</source>
        <translation>Pour un élément masque&#xa0;: ses coefficients contenant le paramètre, par ex. &quot;-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w&quot;.</translation>
    </message>
    <message>
        <source>--mask needs a mask item; &apos;%1&apos; is %2</source>
        <translation type="vanished">--mask demande un élément masque&#xa0;; «&#xa0;%1&#xa0;» est %2</translation>
    </message>
    <message>
        <source>the parameter of --mask must be a name that is not a function or constant (pi, e, sqrt, ...), got &apos;%1&apos;</source>
        <translation type="vanished">le paramètre de --mask doit être un nom qui n&apos;est ni une fonction ni une constante (pi, e, sqrt, ...), reçu «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>the mask &apos;%1&apos; does not contain the parameter &apos;%2&apos;</source>
        <translation type="vanished">le masque «&#xa0;%1&#xa0;» ne contient pas le paramètre «&#xa0;%2&#xa0;»</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no parameter &apos;%3&apos;: omega belongs to the four-point scheme, a and b to corner cutting; a mask item takes --mask with the parameter in its coefficients</source>
        <translation type="vanished">l&apos;élément «&#xa0;%1&#xa0;» (%2) n&apos;a pas de paramètre «&#xa0;%3&#xa0;»&#xa0;: omega appartient au schéma à quatre points, a et b à la découpe des coins&#xa0;; un élément masque prend --mask avec le paramètre dans ses coefficients</translation>
    </message>
    <message>
        <source>the rendering was cancelled</source>
        <translation type="vanished">le rendu a été annulé</translation>
    </message>
    <message>
        <source>the project has no items</source>
        <translation>le projet ne contient aucun élément</translation>
    </message>
    <message>
        <source>no item called &quot;%1&quot;; the items: %2</source>
        <translation>aucun élément ne s’appelle «&#xa0;%1&#xa0;»&#x202f;; les éléments&#xa0;: %2</translation>
    </message>
    <message>
        <source>Set properties of an item and save the project (atomically: all of them or none), or list them. A value is typed as in the Properties dock: a number (3/8 and sqrt(3) too), a choice by its number, its word in the file or its text, true or false, a complex number as 0.5,0.3 or 0.5+0.3i; a structured value (points, matrices, a list) as JSON.</source>
        <translation>Définir des propriétés d’un élément et enregistrer le projet (de façon atomique&#xa0;: toutes ou aucune), ou les lister. Une valeur se saisit comme dans le panneau Propriétés&#xa0;: un nombre (3/8 et sqrt(3) aussi), un choix par son numéro, son mot dans le fichier ou son texte, true ou false, un nombre complexe sous la forme 0.5,0.3 ou 0.5+0.3i&#x202f;; une valeur structurée (points, matrices, liste) en JSON.</translation>
    </message>
    <message>
        <source>Properties to set, in order.</source>
        <translation>Propriétés à définir, dans l’ordre.</translation>
    </message>
    <message>
        <source>The item (default: the first).</source>
        <translation>L’élément (par défaut&#xa0;: le premier).</translation>
    </message>
    <message>
        <source>List the item&apos;s properties: key, type, value, range and choices.</source>
        <translation>Lister les propriétés de l’élément&#xa0;: clé, type, valeur, plage et choix possibles.</translation>
    </message>
    <message>
        <source>With --list: as JSON.</source>
        <translation>Avec --list&#xa0;: en JSON.</translation>
    </message>
    <message>
        <source>expected a project file; see --help</source>
        <translation>fichier de projet attendu&#x202f;; voir --help</translation>
    </message>
    <message>
        <source>--list takes no key=value</source>
        <translation>--list n’accepte pas de key=value</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>(shown, not set)</source>
        <translation>(affiché, non modifiable)</translation>
    </message>
    <message>
        <source>nothing to set: give key=value (or --list)</source>
        <translation>rien à définir&#xa0;: donnez key=value (ou --list)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not key=value</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas de la forme key=value</translation>
    </message>
    <message>
        <source>render an item of a project to PNG, SVG or PDF</source>
        <translation>effectuer le rendu d&apos;un élément d&apos;un projet en PNG, SVG ou PDF</translation>
    </message>
    <message>
        <source>render the frames of an item&apos;s animation (PNG files, MP4/GIF)</source>
        <translation>effectuer le rendu des images de l&apos;animation d&apos;un élément (fichiers PNG, MP4/GIF)</translation>
    </message>
    <message>
        <source>eigenvalues, contractivity, fixed points, dimension (JSON)</source>
        <translation>valeurs propres, contractivité, points fixes, dimension (JSON)</translation>
    </message>
    <message>
        <source>the points of F^k(X0) as CSV</source>
        <translation>les points de F^k(X0) en CSV</translation>
    </message>
    <message>
        <source>set an item&apos;s properties and save, or list them</source>
        <translation>définir les propriétés d’un élément et enregistrer, ou les lister</translation>
    </message>
    <message>
        <source>validate a project file</source>
        <translation>valider un fichier de projet</translation>
    </message>
    <message>
        <source>load and save a project in canonical form</source>
        <translation>charger et enregistrer un projet sous forme canonique</translation>
    </message>
    <message>
        <source>points (PLY), a net or mesh (OBJ), maps (.ifs), matrices (MATLAB)</source>
        <translation>points (PLY), réseau ou maillage (OBJ), applications (.ifs), matrices (MATLAB)</translation>
    </message>
    <message>
        <source>the control polygon after K subdivision steps (JSON)</source>
        <translation>le polygone de contrôle après K étapes de subdivision (JSON)</translation>
    </message>
    <message>
        <source>another tool&apos;s IFS file (Fractint .ifs) as a project</source>
        <translation>le fichier IFS d&apos;un autre outil (Fractint .ifs) comme projet</translation>
    </message>
    <message>
        <source>a mesh file (OBJ, OFF, PLY) as a project with a mesh item</source>
        <translation>un fichier de maillage (OBJ, OFF, PLY) comme projet avec un élément maillage</translation>
    </message>
    <message>
        <source>lambda, mu, Reif&apos;s C1 verdict per valence (Catmull-Clark, Loop)</source>
        <translation>lambda, mu, verdict C1 de Reif par valence (Catmull-Clark, Loop)</translation>
    </message>
    <message>
        <source>where a scheme is C^k as a parameter moves</source>
        <translation>où un schéma est C^k lorsqu&apos;un paramètre varie</translation>
    </message>
    <message>
        <source>re-check the certificate of an exact Hölder exponent</source>
        <translation>revérifier le certificat d&apos;un exposant de Hölder exact</translation>
    </message>
    <message>
        <source>render the built-in paper figures (000 Figs. 2, 3, 5) to PNG</source>
        <translation>rendre en PNG les figures intégrées de l&apos;article (000, fig. 2, 3 et 5)</translation>
    </message>
    <message>
        <source>Usage: attractor-cli &lt;command&gt; [options]</source>
        <translation>Utilisation&#xa0;: attractor-cli &lt;commande&gt; [options]</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>Commandes&#xa0;:</translation>
    </message>
    <message>
        <source>Run &apos;attractor-cli &lt;command&gt; --help&apos; for the options of a command.</source>
        <translation>Exécutez &apos;attractor-cli &lt;commande&gt; --help&apos; pour les options d&apos;une commande.</translation>
    </message>
    <message>
        <source>%1: its %2 entries make a project of %3 MB, more than the %4 MB a project file may be</source>
        <translation>%1 : ses %2 entrées font un projet de %3 Mo, plus que les %4 Mo permis pour un fichier de projet</translation>
    </message>
    <message>
        <source>%1: %2: note: its chaos game does not contract on average (the Lyapunov exponent along its orbit is %3): flam3 draws it by discarding the points that escape</source>
        <translation>%1&#xa0;: %2&#xa0;: note&#xa0;: son jeu du chaos ne contracte pas en moyenne (l’exposant de Lyapunov le long de son orbite vaut %3)&#xa0;: flam3 le dessine en écartant les points qui s’échappent</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit), or every flame of a flam3 genome (.flame, .flam3: flam3, Apophysis, JWildfire): a flame of affine maps as a fractal with control points, any other as a fractal flame item drawn by flam3&apos;s chaos game (a variation this program does not know is named in a warning).</source>
        <translation>Créer un projet à partir du fichier IFS d’un autre outil&#xa0;: chaque entrée d’un fichier .ifs de Fractint (2D et 3D, le format de Fractint, de xfractint et de l’IFS Construction Kit), ou chaque flamme d’un génome flam3 (.flame, .flam3&#xa0;: flam3, Apophysis, JWildfire)&#xa0;: une flamme d’applications affines devient une fractale avec des points de contrôle, toute autre flamme un élément flamme fractale dessiné par le jeu du chaos de flam3 (une variation que ce programme ne connaît pas est nommée dans un avertissement).</translation>
    </message>
    <message>
        <source>attractor-cli: note: all %1 faces are triangles; --scheme loop keeps them triangles (Catmull-Clark makes each one three quads around a new valence-3 vertex)</source>
        <translation>attractor-cli&#xa0;: note&#xa0;: les %1 faces sont toutes des triangles&#x202f;; --scheme loop les conserve en triangles (Catmull-Clark fait de chacune trois quadrilatères autour d’un nouveau sommet de valence 3)</translation>
    </message>
    <message>
        <source>A complex Bézier curve of t = 1/2 + iy in the scaled coordinates g(z, 1/(2y)) of 004 Thm 3.7.3, where it approaches the Takagi graph (the item&apos;s &quot;scaled&quot;, for this figure)</source>
        <translation>Une courbe de Bézier complexe pour t = 1/2 + iy dans les coordonnées mises à l&apos;échelle g(z, 1/(2y)) de 004 Thm 3.7.3, où elle tend vers le graphe de Takagi (le &quot;scaled&quot; de l&apos;élément, pour cette figure)</translation>
    </message>
    <message>
        <source>--scaled draws a complex Bézier curve of t = 1/2 + iy (y ≠ 0) with control points on the real axis; &apos;%1&apos; is not one</source>
        <translation>--scaled trace une courbe de Bézier complexe pour t = 1/2 + iy (y ≠ 0) avec des points de contrôle sur l&apos;axe réel ; &apos;%1&apos; n&apos;en est pas une</translation>
    </message>
    <message>
        <source>attractor-cli: warning: %1</source>
        <translation>attractor-cli&#xa0;: avertissement&#xa0;: %1</translation>
    </message>
    <message>
        <source>  sharp features: %1 creases, %2 corners, %3 holes; boundary %4, crease method %5, triangles %6
</source>
        <translation>  éléments vifs : arêtes vives %1, coins %2, trous %3 ; bord %4, méthode des arêtes vives %5, triangles %6
</translation>
    </message>
    <message>
        <source>Repair what is well defined before the checks: weld boundary vertices at the same position, turn flipped faces over, split vertices whose faces form several fans, name repeated vertices once; say each change.</source>
        <translation type="vanished">Réparer ce qui est bien défini avant les vérifications : souder les sommets de bord à la même position, retourner les faces inversées, scinder les sommets dont les faces forment plusieurs éventails, ne nommer qu&apos;une fois les sommets répétés ; dire chaque modification.</translation>
    </message>
    <message>
        <source>repaired: %1</source>
        <translation>réparé : %1</translation>
    </message>
    <message>
        <source>attractor-cli: not repaired: %1</source>
        <translation>attractor-cli : non réparé : %1</translation>
    </message>
    <message>
        <source>repaired: nothing needed repair</source>
        <translation>réparé : rien à réparer</translation>
    </message>
    <message>
        <source> (--repair would weld %1 vertices, turn %2 faces over and split %3 vertices)</source>
        <translation type="vanished"> (--repair souderait %1 sommets, retournerait %2 faces et scinderait %3 sommets)</translation>
    </message>
    <message>
        <source>name repeated vertices once in %1 faces</source>
        <translation>nommer une seule fois les sommets répétés dans %1 faces</translation>
    </message>
    <message>
        <source>weld %1 vertices</source>
        <translation>souder %1 sommets</translation>
    </message>
    <message>
        <source>turn %1 faces over</source>
        <translation>retourner %1 faces</translation>
    </message>
    <message>
        <source>split %1 vertices</source>
        <translation>scinder %1 sommets</translation>
    </message>
    <message>
        <source> (--repair would %1)</source>
        <translation> (--repair permettrait de %1)</translation>
    </message>
    <message>
        <source>Make a project of a mesh file (OBJ, OFF, PLY ASCII or binary): one subdivision-mesh item with the file&apos;s vertices, in its numbering, and its polygons. A non-manifold mesh (edges of three or more faces, faces of opposite orientations, vertices whose faces form several fans) is drawn as OpenSubdiv draws it, with a note.</source>
        <translation>Crée un projet à partir d’un fichier de maillage (OBJ, OFF, PLY ASCII ou binaire) : un élément maillage de subdivision avec les sommets du fichier, dans sa numérotation, et ses polygones. Un maillage non variété (arêtes de trois faces ou plus, faces d’orientations opposées, sommets dont les faces forment plusieurs éventails) est dessiné comme OpenSubdiv le dessine, avec une note.</translation>
    </message>
    <message>
        <source>Repair what is well defined before the checks: weld boundary vertices at the same position, turn flipped faces over, split vertices whose faces form several fans, name repeated vertices once; say each change (the mesh is then drawn as the repaired surface, not as OpenSubdiv draws the original).</source>
        <translation>Répare ce qui est bien défini avant les vérifications : soude les sommets de bord à la même position, retourne les faces inversées, scinde les sommets dont les faces forment plusieurs éventails, nomme une seule fois les sommets répétés ; indique chaque modification (le maillage est alors dessiné comme la surface réparée, et non comme OpenSubdiv dessine l’original).</translation>
    </message>
    <message>
        <source>attractor-cli: note: the mesh is %1%2</source>
        <translation>attractor-cli: note : le maillage est %1%2</translation>
    </message>
    <message>
        <source>… (%1 in all)</source>
        <translation>… (%1 en tout)</translation>
    </message>
    <message>
        <source>--item NAME is required: %1 has %2 items with an attractor: %3</source>
        <translation>--item NOM est requis : %1 a %2 éléments avec un attracteur : %3</translation>
    </message>
    <message>
        <source>The item (needed when the project has several).</source>
        <translation>L’élément (requis quand le projet en a plusieurs).</translation>
    </message>
    <message>
        <source>--format ply|obj|ifs|flame|matlab and --out FILE are required</source>
        <translation>--format ply|obj|ifs|flame|matlab et --out FICHIER sont requis</translation>
    </message>
    <message>
        <source>Start set: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (plane coordinates; x,y,z for a surface) | lifted:x,y,c1,...;x,y,c1,... (points of the lifted space of 000 §2) | net:i,j,... (control points by index, from 0: the rows of the lifted P) | vertex-limits (a mesh item: the limit positions of the vertices of the mesh refined k times; default: the item&apos;s).</source>
        <translation>Ensemble initial : point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (coordonnées du plan ; x,y,z pour une surface) | lifted:x,y,c1,...;x,y,c1,... (points de l’espace relevé de 000 §2) | net:i,j,... (points de contrôle par indice, à partir de 0 : les lignes de la matrice P relevée) | vertex-limits (élément maillage : les positions limites des sommets du maillage raffiné k fois ; par défaut : celui de l’élément).</translation>
    </message>
    <message>
        <source>%1: %2 % (%3 s</source>
        <translation>%1 : %2 % (%3 s</translation>
    </message>
    <message>
        <source>, about %1 s left</source>
        <translation>, environ %1 s restantes</translation>
    </message>
    <message>
        <source>Report the iteration&apos;s progress on stderr, one line per report (default: on a terminal only, after a second).</source>
        <translation>Indiquer l’avancement de l’itération sur stderr, une ligne par indication (par défaut : sur un terminal seulement, après une seconde).</translation>
    </message>
</context>
<context>
    <name>awb::core</name>
    <message>
        <source>%1: entry (row %2, column %3) is not a finite number</source>
        <translation>%1&#xa0;: le coefficient (ligne %2, colonne %3) n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>matrix rows of different lengths</source>
        <translation>lignes de matrice de longueurs différentes</translation>
    </message>
</context>
<context>
    <name>awb::exchange</name>
    <message>
        <source>%1, line %2, column %3</source>
        <translation>%1, ligne %2, colonne %3</translation>
    </message>
    <message>
        <source>: entry %1</source>
        <translation>&#xa0;: entrée %1</translation>
    </message>
    <message>
        <source>a &apos;}&apos; without its &apos;{&apos;</source>
        <translation>accolade «&#xa0;}&#xa0;» sans accolade «&#xa0;{&#xa0;» correspondante</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not followed by &apos;{&apos;: an entry is NAME { rows }</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas suivi de «&#xa0;{&#xa0;»&#xa0;: une entrée s’écrit NAME { rows }</translation>
    </message>
    <message>
        <source>entry at line %1</source>
        <translation>entrée de la ligne %1</translation>
    </message>
    <message>
        <source>a &apos;{&apos; inside an entry: its &apos;}&apos; is missing</source>
        <translation>accolade «&#xa0;{&#xa0;» à l’intérieur d’une entrée&#xa0;: il manque l’accolade «&#xa0;}&#xa0;» de l’entrée</translation>
    </message>
    <message>
        <source>the file ends before the entry&apos;s &apos;}&apos;</source>
        <translation>le fichier se termine avant l’accolade «&#xa0;}&#xa0;» de l’entrée</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a finite number</source>
        <translation>«&#xa0;%1&#xa0;» n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>the entry has no maps</source>
        <translation>l’entrée n’a aucune application</translation>
    </message>
    <message>
        <source>%1 numbers: a %2D entry has rows of %3 (the map&apos;s coefficients, then its probability), %4 left over</source>
        <translation>%1 nombres&#xa0;: une entrée %2D a des lignes de %3 (les coefficients de l’application, puis sa probabilité), il en reste %4</translation>
    </message>
    <message>
        <source>map %1 has the negative probability %2</source>
        <translation>l’application %1 a une probabilité négative (%2)</translation>
    </message>
    <message>
        <source>a Fractint entry holds maps of the plane or of space, not of dimension %1</source>
        <translation>une entrée Fractint contient des applications du plan ou de l’espace, pas de dimension %1</translation>
    </message>
    <message>
        <source>the entry&apos;s maps are not all of its dimension</source>
        <translation>les applications de l’entrée ne sont pas toutes de sa dimension</translation>
    </message>
    <message>
        <source>entry %1: random iteration leaves every bound (its maps do not contract)</source>
        <translation>entrée %1&#xa0;: l’itération aléatoire dépasse toute borne (ses applications ne sont pas contractantes)</translation>
    </message>
    <message>
        <source>the row starting here runs on to the next line: a %1D entry has rows of %2 numbers (the map&apos;s coefficients, then its probability), one row per line</source>
        <translation>la ligne de nombres qui commence ici se poursuit à la ligne suivante : une entrée %1D a des lignes de %2 nombres (les coefficients de l&apos;application, puis sa probabilité), une par ligne</translation>
    </message>
    <message>
        <source>%1 maps: at most %2 maps are supported</source>
        <translation>%1 applications : au plus %2 applications sont prises en charge</translation>
    </message>
    <message>
        <source>the probabilities sum to %1, not 1: they are used as relative weights</source>
        <translation>les probabilités ont pour somme %1, non 1 : elles servent de poids relatifs</translation>
    </message>
    <message>
        <source>the probabilities are all 0: the maps are chosen with equal probabilities</source>
        <translation>les probabilités sont toutes nulles : les applications sont choisies avec des probabilités égales</translation>
    </message>
    <message>
        <source>a file of bare rows (Fractint 10 and 15: one IFS, no NAME { }) has rows of 7 (2D) or 13 (3D) numbers, its first line %1</source>
        <translation>un fichier de lignes nues (Fractint 10 et 15 : un seul IFS, sans NOM { }) a des lignes de 7 (2D) ou 13 (3D) nombres, sa première ligne %1</translation>
    </message>
    <message>
        <source>a file of bare rows (Fractint 10 and 15) has no braces: an entry is NAME { rows } throughout</source>
        <translation>un fichier de lignes nues (Fractint 10 et 15) n&apos;a pas d&apos;accolades : sinon chaque entrée est NOM { lignes }</translation>
    </message>
    <message>
        <source>%1 more problems</source>
        <translation>%1 problèmes de plus</translation>
    </message>
    <message>
        <source>%1 more entries after the first %2: one file gives at most %2</source>
        <translation>%1 entrées de plus après les %2 premières : un fichier en donne au plus %2</translation>
    </message>
    <message>
        <source>%1 more warnings</source>
        <translation>%1 avertissements de plus</translation>
    </message>
</context>
<context>
    <name>awb::flame</name>
    <message>
        <source>%1: a coefficient is not a finite number</source>
        <translation>%1 : un coefficient n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1: variation %2 does not exist</source>
        <translation>%1 : la variation %2 n&apos;existe pas</translation>
    </message>
    <message>
        <source>%1: the weight of variation %2 is not a finite number</source>
        <translation>%1 : le poids de la variation %2 n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1: its variation parameters are incomplete</source>
        <translation>%1 : ses paramètres de variation sont incomplets</translation>
    </message>
    <message>
        <source>%1: parameter %2 is not a finite number</source>
        <translation>%1 : le paramètre %2 n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1: its colour, colour speed or opacity is not a finite number</source>
        <translation>%1 : sa couleur, sa vitesse de couleur ou son opacité n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>the flame has no xform</source>
        <translation>la flamme n&apos;a aucun xform</translation>
    </message>
    <message>
        <source>the flame has %1 xforms; at most %2 are drawn</source>
        <translation>la flamme a %1 xforms ; au plus %2 sont dessinés</translation>
    </message>
    <message>
        <source>xform %1</source>
        <translation>xform %1</translation>
    </message>
    <message>
        <source>%1: its weight %2 is not a number &gt;= 0</source>
        <translation>%1 : son poids %2 n&apos;est pas un nombre &gt;= 0</translation>
    </message>
    <message>
        <source>%1: its xaos row has %2 entries for %3 xforms</source>
        <translation>%1 : sa ligne xaos a %2 entrées pour %3 xforms</translation>
    </message>
    <message>
        <source>%1: a xaos entry is not a number &gt;= 0</source>
        <translation>%1 : une entrée xaos n&apos;est pas un nombre &gt;= 0</translation>
    </message>
    <message>
        <source>every xform of the flame has weight 0: none is ever chosen</source>
        <translation>chaque xform de la flamme a un poids nul : aucun n&apos;est jamais choisi</translation>
    </message>
    <message>
        <source>xform %1: its xaos row forbids every xform, so an orbit that reaches it cannot go on</source>
        <translation>xform %1 : sa ligne xaos interdit tous les xforms, une orbite qui l&apos;atteint ne peut donc pas continuer</translation>
    </message>
    <message>
        <source>the final xform</source>
        <translation>le xform final</translation>
    </message>
    <message>
        <source>there is no flame to draw</source>
        <translation>il n&apos;y a pas de flamme à dessiner</translation>
    </message>
    <message>
        <source>the spatial filter of radius %1 at supersample %2 would be %3 cells wide; at most %4</source>
        <translation>le filtre spatial de rayon %1 au suréchantillonnage %2 aurait %3 cellules de large ; au plus %4</translation>
    </message>
    <message>
        <source>the spatial filter of radius %1 is too small</source>
        <translation>le filtre spatial de rayon %1 est trop petit</translation>
    </message>
    <message>
        <source>the estimator curve must be &gt; 0</source>
        <translation>la courbe de l&apos;estimateur doit être &gt; 0</translation>
    </message>
    <message>
        <source>the estimator radius %1 must be at least its minimum %2 (and not negative)</source>
        <translation>le rayon %1 de l&apos;estimateur doit être au moins son minimum %2 (et non négatif)</translation>
    </message>
    <message>
        <source>the estimator (radius %1, minimum %2, curve %3) needs too many kernels (%4)</source>
        <translation>l&apos;estimateur (rayon %1, minimum %2, courbe %3) demande trop de noyaux (%4)</translation>
    </message>
    <message>
        <source>the estimator of radius %1 at supersample %2 needs %3 coefficients; at most %4</source>
        <translation>l&apos;estimateur de rayon %1 au suréchantillonnage %2 demande %3 coefficients ; au plus %4</translation>
    </message>
    <message>
        <source>a %1 x %2 picture of the flame at supersample %3 needs %4 x %5 histogram cells; at most 32768 a side</source>
        <translation>une image %1 x %2 de la flamme au suréchantillonnage %3 demande %4 x %5 cellules d&apos;histogramme ; au plus 32768 par côté</translation>
    </message>
    <message>
        <source>a %1 x %2 picture of the flame at supersample %3 needs %4 MB of histograms; at most %5 MB</source>
        <translation>une image %1 x %2 de la flamme au suréchantillonnage %3 demande %4 Mo d&apos;histogrammes ; au plus %5 Mo</translation>
    </message>
    <message>
        <source>the flame&apos;s passes is %1; it takes 1 to %2</source>
        <translation>la flamme a %1 passes ; elle en accepte de 1 à %2</translation>
    </message>
</context>
<context>
    <name>awb::flame::MakeSink</name>
    <message>
        <source>there is no flame to draw</source>
        <translation>il n&apos;y a pas de flamme à dessiner</translation>
    </message>
</context>
<context>
    <name>awb::ifs</name>
    <message>
        <source>the IFS has 1 map (0)</source>
        <translation>l’IFS a 1 application (0)</translation>
    </message>
    <message>
        <source>the IFS has %1 maps (0..%2)</source>
        <translation>l’IFS a %1 applications (0..%2)</translation>
    </message>
    <message>
        <source>no parameter intervals</source>
        <translation>aucun intervalle de paramètre</translation>
    </message>
    <message>
        <source>a parameter interval is empty or not finite</source>
        <translation>un intervalle de paramètre est vide ou non fini</translation>
    </message>
    <message>
        <source>the address has %1 symbols, more than %2</source>
        <translation>l’adresse a %1 symboles, soit plus de %2</translation>
    </message>
    <message>
        <source>symbol %1 of the address is map %2, but %3</source>
        <translation>le symbole %1 de l’adresse est l’application %2, mais %3</translation>
    </message>
    <message>
        <source>the IFS has no maps</source>
        <translation>l’IFS n’a aucune application</translation>
    </message>
    <message>
        <source>the address &apos;%1&apos; has an empty symbol (a comma too many)</source>
        <translation>l’adresse «&#xa0;%1&#xa0;» a un symbole vide (une virgule de trop)</translation>
    </message>
    <message>
        <source>the address &apos;%1&apos; ends with a comma</source>
        <translation>l’adresse «&#xa0;%1&#xa0;» se termine par une virgule</translation>
    </message>
    <message>
        <source>the address is empty: give map numbers such as 0,1,1</source>
        <translation>l’adresse est vide&#xa0;: donnez des numéros d’application tels que 0,1,1</translation>
    </message>
    <message>
        <source>symbol %1 of the address, &apos;%2&apos;, is not a map number (0-based whole number)</source>
        <translation>le symbole %1 de l’adresse, «&#xa0;%2&#xa0;», n’est pas un numéro d’application (entier à partir de 0)</translation>
    </message>
    <message>
        <source>no subdivision matrices</source>
        <translation>aucune matrice de subdivision</translation>
    </message>
    <message>
        <source>the subdivision matrices differ in size</source>
        <translation>les matrices de subdivision n’ont pas toutes la même taille</translation>
    </message>
    <message>
        <source>the parameter %1 is outside [0, 1]</source>
        <translation>le paramètre %1 est en dehors de [0, 1]</translation>
    </message>
    <message>
        <source>an address has 0..%1 symbols</source>
        <translation>une adresse a de 0 à %1 symboles</translation>
    </message>
    <message>
        <source>the parameter interval must satisfy 0 &lt;= t0 &lt; t1 &lt;= 1</source>
        <translation>l’intervalle de paramètre doit vérifier 0 &lt;= t0 &lt; t1 &lt;= 1</translation>
    </message>
    <message>
        <source>the seed point has %1 coordinates, the IFS %2</source>
        <translation>le point de départ a %1 coordonnées, l’IFS en a %2</translation>
    </message>
    <message>
        <source>map 0 does not converge to a fixed point</source>
        <translation>l’application 0 ne converge pas vers un point fixe</translation>
    </message>
    <message>
        <source>iteration depth must be between 0 and %1, got %2</source>
        <translation>la profondeur d’itération doit être comprise entre 0 et %1 (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>the start set is empty</source>
        <translation>l’ensemble initial est vide</translation>
    </message>
    <message>
        <source>start set has %1 coordinates, the IFS space has %2</source>
        <translation>l’ensemble initial a %1 coordonnées, l’espace de l’IFS en a %2</translation>
    </message>
    <message>
        <source>start set</source>
        <translation>ensemble initial</translation>
    </message>
    <message>
        <source>at most 255 maps are supported, got %1</source>
        <translation type="vanished">255 applications au plus sont prises en charge (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>no sink to receive the attractor</source>
        <translation>aucune destination pour recevoir l’attracteur</translation>
    </message>
    <message>
        <source>start point has %1 coordinates, the IFS space has %2</source>
        <translation>le point initial a %1 coordonnées, l’espace de l’IFS en a %2</translation>
    </message>
    <message>
        <source>start point</source>
        <translation>point initial</translation>
    </message>
    <message>
        <source>at most %1 random-iteration samples, got %2</source>
        <translation>%1 échantillons d’itération aléatoire au plus (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>column %1 of %2 sums to %3, not 1: it does not map barycentric points to barycentric points</source>
        <translation>%2, colonne %1&#xa0;: la somme vaut %3, et non 1&#xa0;: les points barycentriques ne sont pas envoyés sur des points barycentriques</translation>
    </message>
    <message>
        <source>the BCIFS has no cell &apos;%1&apos;</source>
        <translation>le BCIFS n’a pas de cellule «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>the BCIFS has no operator &apos;%1&apos;</source>
        <translation>le BCIFS n’a pas d’opérateur «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>the BCIFS has no cells</source>
        <translation>le BCIFS n’a aucune cellule</translation>
    </message>
    <message>
        <source>cell &apos;%1&apos; has dimension %2; it needs at least one control point</source>
        <translation>la cellule «&#xa0;%1&#xa0;» est de dimension %2&#x202f;; il lui faut au moins un point de contrôle</translation>
    </message>
    <message>
        <source>operator &apos;%1&apos; joins a cell that does not exist</source>
        <translation>l’opérateur «&#xa0;%1&#xa0;» relie une cellule qui n’existe pas</translation>
    </message>
    <message>
        <source>operator &apos;%1&apos; (%2 -&gt; %3)</source>
        <translation>opérateur «&#xa0;%1&#xa0;» (%2 -&gt; %3)</translation>
    </message>
    <message>
        <source>%1 joins cells of the wrong kinds: subdivisions join edges or vertices, boundary operators go from an edge to a vertex, placements from the model</source>
        <translation>%1 relie des cellules de types incorrects&#xa0;: les subdivisions relient des arêtes ou des sommets, les opérateurs de bord vont d’une arête à un sommet, les placements partent du modèle</translation>
    </message>
    <message>
        <source>%1 is %2; it must be %3 x %4 (column convention: rows = dimension of &apos;%5&apos;, columns = dimension of &apos;%6&apos;)</source>
        <translation>%1 est de taille %2 au lieu de %3 x %4 (convention par colonnes&#xa0;: lignes = dimension de «&#xa0;%5&#xa0;», colonnes = dimension de «&#xa0;%6&#xa0;»)</translation>
    </message>
    <message>
        <source>edge cell &apos;%1&apos; has no subdivision operator: its attractor would be empty</source>
        <translation>la cellule d’arête «&#xa0;%1&#xa0;» n’a pas d’opérateur de subdivision&#xa0;: son attracteur serait vide</translation>
    </message>
    <message>
        <source>constraint %1</source>
        <translation>contrainte %1</translation>
    </message>
    <message>
        <source>%1 has an empty side or an unknown operator</source>
        <translation>%1 a un membre vide ou un opérateur inconnu</translation>
    </message>
    <message>
        <source>%1: %2 ends at &apos;%3&apos; but %4 starts at &apos;%5&apos;</source>
        <translation>%1&#xa0;: %2 se termine en «&#xa0;%3&#xa0;» mais %4 commence en «&#xa0;%5&#xa0;»</translation>
    </message>
    <message>
        <source>%1 (%2) compares paths between different cells</source>
        <translation>%1 (%2) compare des chemins entre des cellules différentes</translation>
    </message>
    <message>
        <source>%1 constraint %2 %3 is violated by %4 (entry row %5, column %6)</source>
        <translation>la contrainte %1 %2 %3 est violée avec un écart de %4 (coefficient en ligne %5, colonne %6)</translation>
    </message>
    <message>
        <source>; also violated:</source>
        <translation>&#x202f;; également violées&#xa0;:</translation>
    </message>
    <message>
        <source>edge cell &apos;%1&apos; has no placement (control points): it cannot be drawn</source>
        <translation>la cellule d’arête «&#xa0;%1&#xa0;» n’a pas de placement (points de contrôle)&#xa0;: elle ne peut pas être tracée</translation>
    </message>
    <message>
        <source>the junction matrix must be square and at least 2 x 2, got %1</source>
        <translation>la matrice de jonction doit être carrée et au moins de taille 2 x 2 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the copy&apos;s placement must have %1 rows (one per control point of the junction), got %2</source>
        <translation>le placement de la copie doit avoir %1 lignes (une par point de contrôle de la jonction) (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>the junction has %1 control points, got %2</source>
        <translation>la jonction a %1 points de contrôle (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>junction matrix</source>
        <translation>matrice de jonction</translation>
    </message>
    <message>
        <source>copy placement</source>
        <translation>placement de la copie</translation>
    </message>
    <message>
        <source>the junction matrix</source>
        <translation>la matrice de jonction</translation>
    </message>
    <message>
        <source>the copy placement</source>
        <translation>le placement de la copie</translation>
    </message>
    <message>
        <source>the copies collapse onto the fixed point: no tangent information</source>
        <translation>les copies se réduisent au point fixe&#xa0;: aucune information de tangente</translation>
    </message>
    <message>
        <source>lambda = %1: %2</source>
        <translation>lambda = %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>; |lambda| &gt;= 1, so the junction matrix does not contract</source>
        <translation>&#x202f;; |lambda| &gt;= 1, donc la matrice de jonction n’est pas contractante</translation>
    </message>
    <message>
        <source> (the copy has no component along the subdominant eigenvector, lambda = %1, so the next eigenvalue governs)</source>
        <translation> (la copie n’a pas de composante selon le vecteur propre sous-dominant, lambda = %1, donc c’est la valeur propre suivante qui détermine le comportement)</translation>
    </message>
    <message>
        <source> (the eigenvectors are not complete; the copy&apos;s components were not examined)</source>
        <translation> (les vecteurs propres ne forment pas une base&#x202f;; les composantes de la copie n’ont pas été examinées)</translation>
    </message>
    <message>
        <source>vertex subdivisions must be square and non-empty, got %1 and %2</source>
        <translation>les subdivisions de sommet doivent être carrées et non vides (reçu&#xa0;: %1 et %2)</translation>
    </message>
    <message>
        <source>the free columns must have %1 rows (n_l + n_r), got X %2 and Y %3</source>
        <translation>les colonnes libres doivent avoir %1 lignes (n_l + n_r) (reçu&#xa0;: X %2 et Y %3)</translation>
    </message>
    <message>
        <source>free columns X of T^l</source>
        <translation>colonnes libres X de T^l</translation>
    </message>
    <message>
        <source>free columns Y of T^r</source>
        <translation>colonnes libres Y de T^r</translation>
    </message>
    <message>
        <source>the free columns X of T^l</source>
        <translation>les colonnes libres X de T^l</translation>
    </message>
    <message>
        <source>the free columns Y of T^r</source>
        <translation>les colonnes libres Y de T^r</translation>
    </message>
    <message>
        <source>the %1 curve&apos;s subdivision operators must both be m x m, got %2 and %3</source>
        <translation>les opérateurs de subdivision de la courbe %1 doivent être tous deux de taille m x m (reçu&#xa0;: %2 et %3)</translation>
    </message>
    <message>
        <source>the %1 curve&apos;s vertex dimension must be in 1..%2, got %3</source>
        <translation>la dimension de sommet de la courbe %1 doit être dans 1..%2 (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>the %1 curve needs %2 control points, got %3</source>
        <translation>la courbe %1 demande %2 points de contrôle (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>control points of the %1 curve</source>
        <translation>points de contrôle de la courbe %1</translation>
    </message>
    <message>
        <source>both curves&apos; control points must have the same dimension</source>
        <translation>les points de contrôle des deux courbes doivent avoir la même dimension</translation>
    </message>
    <message>
        <source>X must have m_l - n_l columns and Y m_r - n_r</source>
        <translation>X doit avoir m_l - n_l colonnes et Y m_r - n_r</translation>
    </message>
    <message>
        <source>junction parameter %1 is not a finite number</source>
        <translation>le paramètre de jonction %1 n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>T^i has no subdominant eigenvalue</source>
        <translation>T^i n’a pas de valeur propre sous-dominante</translation>
    </message>
    <message>
        <source>lambda_2 = %1 (%2)</source>
        <translation>lambda_2 = %1 (%2)</translation>
    </message>
    <message>
        <source>: |lambda_2| &gt;= 1, T^i does not contract and the junction does not converge</source>
        <translation>&#xa0;: |lambda_2| &gt;= 1, T^i n’est pas contractante et la jonction ne converge pas</translation>
    </message>
    <message>
        <source>: both sides have half-tangents along the same eigenvector, from opposite sides: G1 at the junction point</source>
        <translation>&#xa0;: les deux côtés ont des demi-tangentes selon le même vecteur propre, de sens opposés&#xa0;: G1 au point de jonction</translation>
    </message>
    <message>
        <source>: both sides have half-tangents, but they are not opposite (a corner or cusp)</source>
        <translation>&#xa0;: les deux côtés ont des demi-tangentes, mais elles ne sont pas opposées (un coin ou un point de rebroussement)</translation>
    </message>
    <message>
        <source>the cubic needs 4 and the quadratic 3 control points of one dimension, got %1 and %2</source>
        <translation>la cubique demande 4 points de contrôle et la quadratique 3, tous de même dimension (reçu&#xa0;: %1 et %2)</translation>
    </message>
    <message>
        <source>%1 must exceed the other eigenvalues of %2 (largest modulus %3) to be subdominant, and be below 1 for %2 to contract</source>
        <translation>%1 doit dépasser les autres valeurs propres de %2 (module maximal %3) pour être sous-dominante, et être inférieure à 1 pour que %2 soit contractante</translation>
    </message>
    <message>
        <source>refined junction parameter %1 is not a finite number</source>
        <translation>le paramètre de jonction raffinée %1 n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>refined junction parameter %1 = %2 is outside its admissible range (%3, %4): %5</source>
        <translation>le paramètre de jonction raffinée %1 = %2 est en dehors de son intervalle admissible (%3, %4)&#xa0;: %5</translation>
    </message>
    <message>
        <source>the refined junction needs 4 cubic, 3 quadratic and 3 handle control points of one dimension, got %1, %2 and %3</source>
        <translation>la jonction raffinée demande 4 points de contrôle cubiques, 3 quadratiques et 3 poignées, tous de même dimension (reçu&#xa0;: %1, %2 et %3)</translation>
    </message>
    <message>
        <source>handles of the refined junction</source>
        <translation>poignées de la jonction raffinée</translation>
    </message>
    <message>
        <source>the split parameter u is not a finite number</source>
        <translation>le paramètre de découpe u n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>the split parameter u = %1 must lie strictly between 0 and 1 (002 §4: 0 &lt; u &lt; 1)</source>
        <translation>le paramètre de découpe u = %1 doit être strictement compris entre 0 et 1 (002 §4&#xa0;: 0 &lt; u &lt; 1)</translation>
    </message>
    <message>
        <source>coincide</source>
        <comment>points</comment>
        <translation>sont confondus</translation>
    </message>
    <message>
        <source>are collinear</source>
        <comment>points</comment>
        <translation>sont alignés</translation>
    </message>
    <message>
        <source>are coplanar</source>
        <comment>points</comment>
        <translation>sont coplanaires</translation>
    </message>
    <message>
        <source>the affine map is not invertible (its linear part is singular)</source>
        <translation>l’application affine n’est pas inversible (sa partie linéaire est singulière)</translation>
    </message>
    <message>
        <source>an affine map of R^%1 is fixed by %2 point pairs</source>
        <translation>une application affine de R^%1 est déterminée par %2 paires de points</translation>
    </message>
    <message>
        <source>source points</source>
        <translation>points sources</translation>
    </message>
    <message>
        <source>target points</source>
        <translation>points cibles</translation>
    </message>
    <message>
        <source>the source points %1: no unique affine map takes them to the targets</source>
        <translation>les points sources %1&#xa0;: aucune application affine unique ne les envoie sur les cibles</translation>
    </message>
    <message>
        <source>fractal interpolation needs N + 1 &gt;= 3 data points (x, y)</source>
        <translation>l’interpolation fractale demande N + 1 &gt;= 3 points de données (x, y)</translation>
    </message>
    <message>
        <source>interpolation data</source>
        <translation>données d’interpolation</translation>
    </message>
    <message>
        <source>fractal interpolation through %1 points needs %2 vertical scalings d_n, got %3</source>
        <translation>l’interpolation fractale par %1 points demande %2 facteurs d’échelle verticaux d_n (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>interpolation abscissae must increase (x_%1 &lt;= x_%2)</source>
        <translation>les abscisses d’interpolation doivent être croissantes (x_%1 &lt;= x_%2)</translation>
    </message>
    <message>
        <source>vertical scaling d_%1 = %2 must satisfy |d_n| &lt; 1</source>
        <translation>le facteur d’échelle vertical d_%1 = %2 doit vérifier |d_n| &lt; 1</translation>
    </message>
    <message>
        <source>002 §5 needs three control points in the plane (3 x 2)</source>
        <translation>002 §5 demande trois points de contrôle dans le plan (3 x 2)</translation>
    </message>
    <message>
        <source>control points</source>
        <translation>points de contrôle</translation>
    </message>
    <message>
        <source>control points Q0, Q1, Q2 are collinear: the map omega of 002 §5 is not invertible</source>
        <translation>les points de contrôle Q0, Q1, Q2 sont alignés&#xa0;: l’application oméga de 002 §5 n’est pas inversible</translation>
    </message>
    <message>
        <source>a Bézier curve needs at least 2 control points (degree &gt;= 1), got %1</source>
        <translation>une courbe de Bézier demande au moins 2 points de contrôle (degré &gt;= 1) (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>control points must have 1 to 3 coordinates</source>
        <translation>les points de contrôle doivent avoir de 1 à 3 coordonnées</translation>
    </message>
    <message>
        <source>the %1 control points %2, so the affine maps of eqs. (9)-(10) are not unique</source>
        <translation>les %1 points de contrôle %2, donc les applications affines des éq. (9)-(10) ne sont pas uniques</translation>
    </message>
    <message>
        <source>no affine map of R^%1 takes the control polygon of this degree-%2 curve to its de Casteljau pieces (mismatch %3): the pieces are not affine images of the curve in its own space</source>
        <translation>aucune application affine de R^%1 n’envoie le polygone de contrôle de cette courbe de degré %2 sur ses morceaux de de Casteljau (écart %3)&#xa0;: les morceaux ne sont pas des images affines de la courbe dans son propre espace</translation>
    </message>
    <message>
        <source>; the maps act on barycentric coordinates R^%1 (%2)</source>
        <translation>&#x202f;; les applications agissent sur les coordonnées barycentriques R^%1 (%2)</translation>
    </message>
    <message>
        <source>; the maps act on the lifted space R^%1 of 000 §2, drawn through its first %2 coordinates</source>
        <translation>&#x202f;; les applications agissent sur l’espace relevé R^%1 de 000 §2, tracé par ses %2 premières coordonnées</translation>
    </message>
    <message>
        <source>map 1 has spectral radius %1, map 2 %2; %3 levels shrink every piece to 1/1000 of the curve</source>
        <translation>l’application 1 a pour rayon spectral %1, l’application 2 %2&#x202f;; %3 niveaux réduisent chaque morceau à 1/1000 de la courbe</translation>
    </message>
    <message>
        <source>. u = %1 is close to %2: map %3 is nearly non-contractive and the pieces are very unequal (random iteration, or u nearer 1/2, converges faster)</source>
        <translation>. u = %1 est proche de %2&#xa0;: l’application %3 est presque non contractante et les morceaux sont très inégaux (l’itération aléatoire, ou un u plus proche de 1/2, converge plus vite)</translation>
    </message>
    <message>
        <source>. Map %1 is not a Euclidean contraction (||A||_2 = %2) but is eventually contractive, as 002 §5 allows</source>
        <translation>. L’application %1 n’est pas une contraction euclidienne (||A||_2 = %2) mais elle est contractante à terme, ce que 002 §5 autorise</translation>
    </message>
    <message>
        <source>a combined IFS needs at least one curve</source>
        <translation>un IFS combiné demande au moins une courbe</translation>
    </message>
    <message>
        <source>curve %1</source>
        <translation>courbe %1</translation>
    </message>
    <message>
        <source>%1: the combined IFS of 002 §6 acts on the plane, control points need 2 coordinates</source>
        <translation>%1&#xa0;: l’IFS combiné de 002 §6 agit sur le plan, les points de contrôle doivent avoir 2 coordonnées</translation>
    </message>
    <message>
        <source>%1: its maps do not act on the plane (%2), so they cannot be combined with the other curves&apos; maps</source>
        <translation>%1&#xa0;: ses applications n’agissent pas sur le plan (%2), elles ne peuvent donc pas être combinées avec celles des autres courbes</translation>
    </message>
    <message>
        <source>a union needs at least one curve</source>
        <translation>une union demande au moins une courbe</translation>
    </message>
    <message>
        <source>arc &apos;%1&apos; (%2 -&gt; %3)</source>
        <translation>arc «&#xa0;%1&#xa0;» (%2 -&gt; %3)</translation>
    </message>
    <message>
        <source>the automaton has no states</source>
        <translation>l’automate n’a aucun état</translation>
    </message>
    <message>
        <source>state &apos;%1&apos; has no control points</source>
        <translation>l’état «&#xa0;%1&#xa0;» n’a pas de points de contrôle</translation>
    </message>
    <message>
        <source>state &apos;%1&apos;: control points must be 2D or 3D, got %2 coordinates</source>
        <translation>état «&#xa0;%1&#xa0;»&#xa0;: les points de contrôle doivent être en 2D ou en 3D (reçu&#xa0;: %2 coordonnées)</translation>
    </message>
    <message>
        <source>control points of state &apos;%1&apos;</source>
        <translation>points de contrôle de l’état «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>at most 255 arcs are supported (addresses are bytes), got %1</source>
        <translation>255 arcs au plus sont pris en charge (les adresses sont des octets) (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>arc &apos;%1&apos; connects states %2 -&gt; %3, but the automaton has %4 states</source>
        <translation>l’arc «&#xa0;%1&#xa0;» relie les états %2 -&gt; %3, mais l’automate a %4 états</translation>
    </message>
    <message>
        <source>%1 has a %2 x %3 matrix; it must be %4 x %5 (row convention: rows = dimension of &apos;%6&apos;, columns = dimension of &apos;%7&apos;)</source>
        <translation>%1 a une matrice %2 x %3 au lieu de %4 x %5 (convention par lignes&#xa0;: lignes = dimension de «&#xa0;%6&#xa0;», colonnes = dimension de «&#xa0;%7&#xa0;»)</translation>
    </message>
    <message>
        <source>row %1 of %2 sums to %3, not 1: the map does not keep barycentric coordinates summing to 1</source>
        <translation>%2, ligne %1&#xa0;: la somme vaut %3, et non 1&#xa0;: l’application ne conserve pas la somme 1 des coordonnées barycentriques</translation>
    </message>
    <message>
        <source>the weight of %1 must be a finite number &gt; 0, got %2</source>
        <translation>le poids de %1 doit être un nombre fini &gt; 0 (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>state &apos;%1&apos; has no outgoing arc: its attractor would be empty</source>
        <translation>l’état «&#xa0;%1&#xa0;» n’a pas d’arc sortant&#xa0;: son attracteur serait vide</translation>
    </message>
    <message>
        <source>the barycentric part needs a non-empty square matrix</source>
        <translation>la partie barycentrique demande une matrice carrée non vide</translation>
    </message>
    <message>
        <source>cycle %1 has spectral radius %2 &gt;= 1 on the barycentric directions: repeating it does not contract, so the automaton has no attractor</source>
        <translation>le cycle %1 a un rayon spectral %2 &gt;= 1 sur les directions barycentriques&#xa0;: sa répétition n’est pas contractante, donc l’automate n’a pas d’attracteur</translation>
    </message>
    <message>
        <source>a fixed point needs a non-empty square matrix</source>
        <translation>un point fixe demande une matrice carrée non vide</translation>
    </message>
    <message>
        <source>the fixed point is not unique: 1 is a repeated eigenvalue</source>
        <translation>le point fixe n’est pas unique&#xa0;: 1 est une valeur propre multiple</translation>
    </message>
    <message>
        <source>state %1 does not exist: the automaton has %2 states</source>
        <translation>l’état %1 n’existe pas&#xa0;: l’automate a %2 états</translation>
    </message>
    <message>
        <source>one start set per state is needed: the automaton has %1 states, got %2 start sets</source>
        <translation>il faut un ensemble initial par état&#xa0;: l’automate a %1 états (reçu&#xa0;: %2 ensembles initiaux)</translation>
    </message>
    <message>
        <source>start set of state &apos;%1&apos;</source>
        <translation>ensemble initial de l’état «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 est vide</translation>
    </message>
    <message>
        <source>%1 has %2 coordinates, the state&apos;s space has %3</source>
        <translation>%1 a %2 coordonnées, l’espace de l’état en a %3</translation>
    </message>
    <message>
        <source>at most 4e9 random-iteration samples, got %1</source>
        <translation>4e9 échantillons d’itération aléatoire au plus (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the affine map&apos;s translation does not match its linear part</source>
        <translation>la translation de l’application affine ne correspond pas à sa partie linéaire</translation>
    </message>
    <message>
        <source>a barycentric frame in %1D needs %2 points, got a %3 x %4 matrix</source>
        <translation>un repère barycentrique en %1D demande %2 points (reçu&#xa0;: une matrice %3 x %4)</translation>
    </message>
    <message>
        <source>domain frame</source>
        <translation>repère de départ</translation>
    </message>
    <message>
        <source>image frame</source>
        <translation>repère d’arrivée</translation>
    </message>
    <message>
        <source>affine map</source>
        <translation>application affine</translation>
    </message>
    <message>
        <source>the image frame&apos;s points are affinely dependent (collinear in 2D)</source>
        <translation>les points du repère d’arrivée sont affinement dépendants (alignés en 2D)</translation>
    </message>
    <message>
        <source>map %1 does not act on the same space as map 1</source>
        <translation>l’application %1 n’agit pas sur le même espace que l’application 1</translation>
    </message>
    <message>
        <source>map %1 (linear part)</source>
        <translation>application %1 (partie linéaire)</translation>
    </message>
    <message>
        <source>map %1 (translation)</source>
        <translation>application %1 (translation)</translation>
    </message>
    <message>
        <source>view %1 does not fit the IFS space</source>
        <translation>la vue %1 ne correspond pas à l’espace de l’IFS</translation>
    </message>
    <message>
        <source>the IFS has %1 maps but %2 probabilities</source>
        <translation>l’IFS a %1 applications mais %2 probabilités</translation>
    </message>
    <message>
        <source>probability of map %1 must be a finite number &gt;= 0</source>
        <translation>la probabilité de l’application %1 doit être un nombre fini &gt;= 0</translation>
    </message>
    <message>
        <source>the map probabilities sum to 0</source>
        <translation>la somme des probabilités des applications est nulle</translation>
    </message>
    <message>
        <source>the lifting needs %1 distinct free rows of the control points</source>
        <translation>le relèvement demande %1 lignes libres distinctes des points de contrôle</translation>
    </message>
    <message>
        <source> and </source>
        <translation> et </translation>
    </message>
    <message>
        <source>the lifted matrix P is nearly singular (reciprocal condition number %1): M_i = P^-1 S_i P lose about %2 of 16 significant digits; control points %3 are almost collinear</source>
        <translation>la matrice relevée P est presque singulière (inverse du conditionnement %1)&#xa0;: M_i = P^-1 S_i P perd environ %2 des 16 chiffres significatifs&#x202f;; les points de contrôle %3 sont presque alignés</translation>
    </message>
    <message>
        <source>the lifted matrix P is nearly singular (reciprocal condition number %1): M_i = P^-1 S_i P lose about %2 of 16 significant digits; control points %3 are almost coplanar</source>
        <translation>la matrice relevée P est presque singulière (inverse du conditionnement %1)&#xa0;: M_i = P^-1 S_i P perd environ %2 des 16 chiffres significatifs&#x202f;; les points de contrôle %3 sont presque coplanaires</translation>
    </message>
    <message>
        <source>control points %1 are collinear, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>les points de contrôle %1 sont alignés, donc la matrice relevée P de 000 §2 est singulière et M_i = P^-1 S_i P n’est pas définie&#x202f;; l’attracteur est calculé sous forme barycentrique</translation>
    </message>
    <message>
        <source>control points %1 are coplanar, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>les points de contrôle %1 sont coplanaires, donc la matrice relevée P de 000 §2 est singulière et M_i = P^-1 S_i P n’est pas définie&#x202f;; l’attracteur est calculé sous forme barycentrique</translation>
    </message>
    <message>
        <source>control points %1 are affinely dependent, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>les points de contrôle %1 sont affinement dépendants, donc la matrice relevée P de 000 §2 est singulière et M_i = P^-1 S_i P n’est pas définie&#x202f;; l’attracteur est calculé sous forme barycentrique</translation>
    </message>
    <message>
        <source>matrix S_%1 does not match %2 control points</source>
        <translation>la matrice S_%1 ne correspond pas à %2 points de contrôle</translation>
    </message>
    <message>
        <source>matrix S_%1</source>
        <translation>matrice S_%1</translation>
    </message>
    <message>
        <source>start points must have %1 (plane) or %2 (barycentric) coordinates</source>
        <translation>les points initiaux doivent avoir %1 coordonnées (plan) ou %2 coordonnées (barycentriques)</translation>
    </message>
    <message>
        <source>start points must have %1 (plane) or %2 (lifted) coordinates</source>
        <translation>les points initiaux doivent avoir %1 coordonnées (plan) ou %2 coordonnées (espace relevé)</translation>
    </message>
    <message>
        <source>a union needs at least one component</source>
        <translation>une union demande au moins une composante</translation>
    </message>
    <message>
        <source>component %1 has %2 maps, component 1 has %3: a block union needs equally many</source>
        <translation>la composante %1 a %2 applications, la composante 1 en a %3&#xa0;: une union par blocs en demande autant pour chacune</translation>
    </message>
    <message>
        <source>probabilities must be finite and non-negative</source>
        <translation>les probabilités doivent être finies et positives ou nulles</translation>
    </message>
    <message>
        <source>the probabilities sum to zero</source>
        <translation>la somme des probabilités est nulle</translation>
    </message>
    <message>
        <source>the lattice lists %1 coordinates for %2 control points</source>
        <translation>la grille donne %1 coordonnées pour %2 points de contrôle</translation>
    </message>
    <message>
        <source>a map is listed twice among the maps used</source>
        <translation>une application figure deux fois parmi les applications utilisées</translation>
    </message>
    <message>
        <source>map index %1 is out of range: the %2 layout has maps 0 to %3</source>
        <translation>l’indice d’application %1 est hors limites&#xa0;: la disposition %2 a les applications 0 à %3</translation>
    </message>
    <message>
        <source>at most %1 maps are supported, got %2</source>
        <translation>au plus %1 applications sont prises en charge, reçu %2</translation>
    </message>
    <message>
        <source>the barycentric part needs a non-empty matrix</source>
        <translation>la partie barycentrique nécessite une matrice non vide</translation>
    </message>
</context>
<context>
    <name>awb::mesh</name>
    <message>
        <source>the mesh has no vertices</source>
        <translation>le maillage n’a aucun sommet</translation>
    </message>
    <message>
        <source>the mesh has no faces</source>
        <translation>le maillage n’a aucune face</translation>
    </message>
    <message>
        <source>face %1 has %2 vertices; a face needs at least 3</source>
        <translation>la face %1 a %2 sommets ; une face en demande au moins 3</translation>
    </message>
    <message>
        <source>face %1 refers to vertex %2, but the mesh has %3 vertices (0 to %4)</source>
        <translation>la face %1 renvoie au sommet %2, mais le maillage a %3 sommets (0 à %4)</translation>
    </message>
    <message>
        <source>face %1 lists vertex %2 twice</source>
        <translation>la face %1 cite deux fois le sommet %2</translation>
    </message>
    <message>
        <source>edge (%1, %2) is non-manifold: faces %3 meet there</source>
        <translation>l’arête (%1, %2) n’est pas une variété : les faces %3 s’y rencontrent</translation>
    </message>
    <message>
        <source>faces %1 and %2 are oriented inconsistently: both run from vertex %3 to vertex %4 (turn one of them over)</source>
        <translation>les faces %1 et %2 sont orientées de façon incohérente : toutes deux vont du sommet %3 au sommet %4 (retournez l’une d’elles)</translation>
    </message>
    <message>
        <source>vertex %1 is non-manifold: its %2 faces do not form one fan around it</source>
        <translation>le sommet %1 n’est pas une variété : ses %2 faces ne forment pas un seul éventail autour de lui</translation>
    </message>
    <message>
        <source>mesh vertices need 3 coordinates, got %1</source>
        <translation>les sommets du maillage demandent 3 coordonnées, reçu %1</translation>
    </message>
    <message>
        <source>vertex %1 has a coordinate that is not a finite number</source>
        <translation>le sommet %1 a une coordonnée qui n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>face %1 has %2 vertices; Loop subdivision takes triangles only</source>
        <translation>la face %1 a %2 sommets ; la subdivision de Loop ne prend que des triangles</translation>
    </message>
    <message>
        <source>a vertex&apos;s valence must be 3 to 64, got %1</source>
        <translation>la valence d’un sommet doit être de 3 à 64, reçu %1</translation>
    </message>
    <message>
        <source>a characteristic map needs ring x 2 points</source>
        <translation>une application caractéristique demande les points de l’anneau × 2</translation>
    </message>
    <message>
        <source>a grid needs 1 to 1000 quads a side, got %1 x %2</source>
        <translation>une grille demande 1 à 1000 quadrilatères par côté (reçu&#xa0;: %1 x %2)</translation>
    </message>
    <message>
        <source>there is no example mesh &apos;%1&apos;</source>
        <translation>il n’y a pas de maillage d’exemple «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1, ligne %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1 : « %2 » n&apos;est pas un nombre</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a finite number</source>
        <translation>%1&#xa0;: «&#xa0;%2&#xa0;» n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a whole number</source>
        <translation>%1&#xa0;: «&#xa0;%2&#xa0;» n’est pas un nombre entier</translation>
    </message>
    <message>
        <source>%1: a vertex needs 3 coordinates, this one has %2</source>
        <translation>%1&#xa0;: un sommet demande 3 coordonnées, celui-ci en a %2</translation>
    </message>
    <message>
        <source>%1: a face needs at least 3 vertices, this one has %2</source>
        <translation>%1&#xa0;: une face demande au moins 3 sommets, celle-ci en a %2</translation>
    </message>
    <message>
        <source>%1: vertex index %2 is out of range (the file has %3 vertices)</source>
        <translation>%1&#xa0;: l’indice de sommet %2 est hors limites (le fichier a %3 sommets)</translation>
    </message>
    <message>
        <source>%1 holds no vertices</source>
        <translation>%1 ne contient aucun sommet</translation>
    </message>
    <message>
        <source>%1 holds no faces: not a polygon mesh</source>
        <translation>%1 ne contient aucune face&#xa0;: ce n’est pas un maillage polygonal</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a face corner (v, v/vt, v//vn or v/vt/vn, nonzero whole numbers)</source>
        <translation>%1&#xa0;: «&#xa0;%2&#xa0;» n’est pas un coin de face (v, v/vt, v//vn ou v/vt/vn, entiers non nuls)</translation>
    </message>
    <message>
        <source>%1: relative vertex index %2 is out of range (%3 vertices precede it)</source>
        <translation>%1&#xa0;: l’indice de sommet relatif %2 est hors limites (%3 sommets le précèdent)</translation>
    </message>
    <message>
        <source>%1 is not a valid OBJ file (tinyobjloader: %2)</source>
        <translation>%1 n’est pas un fichier OBJ valide (tinyobjloader&#xa0;: %2)</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 est vide</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a header this reader takes: ASCII OFF of 3D points ([ST][C][N]OFF)</source>
        <translation>%1&#xa0;: «&#xa0;%2&#xa0;» n’est pas un en-tête que ce lecteur accepte&#xa0;: OFF ASCII de points 3D ([ST][C][N]OFF)</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not the counts line (vertices, faces and edges) of an OFF file</source>
        <translation>%1&#xa0;: «&#xa0;%2&#xa0;» n’est pas la ligne des nombres (de sommets, de faces et d’arêtes) d’un fichier OFF</translation>
    </message>
    <message>
        <source>%1: %2 vertices and %3 faces need more lines than the %4 left in the file</source>
        <translation>%1&#xa0;: %2 sommets et %3 faces demandent plus de lignes que les %4 qui restent dans le fichier</translation>
    </message>
    <message>
        <source>%1 ends after %2 of its %3 vertices</source>
        <translation>%1 se termine après %2 de ses %3 sommets</translation>
    </message>
    <message>
        <source>%1 ends after %2 of its %3 faces</source>
        <translation>%1 se termine après %2 de ses %3 faces</translation>
    </message>
    <message>
        <source>%1: the face announces %2 vertices but lists %3</source>
        <translation>%1&#xa0;: la face annonce %2 sommets mais en cite %3</translation>
    </message>
    <message>
        <source>%1: data after the last face (the counts announce %2 vertices and %3 faces)</source>
        <translation>%1&#xa0;: données après la dernière face (les nombres annoncent %2 sommets et %3 faces)</translation>
    </message>
    <message>
        <source>%1: a property outside any element</source>
        <translation>%1&#xa0;: une propriété hors de tout élément</translation>
    </message>
    <message>
        <source>%1: unknown PLY property type &apos;%2&apos;</source>
        <translation>%1&#xa0;: type de propriété PLY inconnu «&#xa0;%2&#xa0;»</translation>
    </message>
    <message>
        <source>%1: a list&apos;s length needs a whole-number type</source>
        <translation>%1&#xa0;: la longueur d’une liste demande un type entier</translation>
    </message>
    <message>
        <source>%1: property %2 appears twice in element %3</source>
        <translation>%1&#xa0;: la propriété %2 apparaît deux fois dans l’élément %3</translation>
    </message>
    <message>
        <source>%1 is not a PLY file (its first line is not &apos;ply&apos;)</source>
        <translation>%1 n’est pas un fichier PLY (sa première ligne n’est pas «&#xa0;ply&#xa0;»)</translation>
    </message>
    <message>
        <source>%1: the PLY header has no end_header line</source>
        <translation>%1&#xa0;: l’en-tête PLY n’a pas de ligne end_header</translation>
    </message>
    <message>
        <source>%1: unsupported PLY format &apos;%2&apos; (ascii, binary_little_endian or binary_big_endian 1.0)</source>
        <translation>%1&#xa0;: format PLY «&#xa0;%2&#xa0;» non pris en charge (ascii, binary_little_endian ou binary_big_endian 1.0)</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a valid count</source>
        <translation>%1&#xa0;: «&#xa0;%2&#xa0;» n’est pas un nombre d’éléments valide</translation>
    </message>
    <message>
        <source>%1: element %2 appears twice</source>
        <translation>%1&#xa0;: l’élément %2 apparaît deux fois</translation>
    </message>
    <message>
        <source>%1: unknown PLY header line &apos;%2&apos;</source>
        <translation type="vanished">%1&#xa0;: ligne d’en-tête PLY inconnue «&#xa0;%2&#xa0;»</translation>
    </message>
    <message>
        <source>%1: the PLY header has no format line</source>
        <translation>%1&#xa0;: l’en-tête PLY n’a pas de ligne format</translation>
    </message>
    <message>
        <source>%1: the vertex element needs the scalar properties x, y and z</source>
        <translation>%1&#xa0;: l’élément vertex demande les propriétés scalaires x, y et z</translation>
    </message>
    <message>
        <source>%1: the face element needs one list property vertex_indices (or vertex_index) of whole numbers</source>
        <translation>%1&#xa0;: l’élément face demande une propriété liste vertex_indices (ou vertex_index) d’entiers</translation>
    </message>
    <message>
        <source>%1, line %2 (%3 %4)</source>
        <translation>%1, ligne %2 (%3 %4)</translation>
    </message>
    <message>
        <source>%1, %2 %3 (byte %4)</source>
        <translation>%1, %2 %3 (octet %4)</translation>
    </message>
    <message>
        <source>%1: element %2 claims %3 items, more than the rest of the file can hold</source>
        <translation>%1&#xa0;: l’élément %2 annonce %3 entrées, plus que le reste du fichier ne peut en contenir</translation>
    </message>
    <message>
        <source>%1: the data ends early (truncated)</source>
        <translation>%1&#xa0;: les données s’arrêtent trop tôt (fichier tronqué)</translation>
    </message>
    <message>
        <source>%1: data after the last element (the header&apos;s counts do not match the data)</source>
        <translation>%1&#xa0;: données après le dernier élément (les nombres de l’en-tête ne correspondent pas aux données)</translation>
    </message>
    <message>
        <source>%1, byte %2</source>
        <translation>%1, octet %2</translation>
    </message>
    <message>
        <source>%1: list length %2 is negative</source>
        <translation>%1&#xa0;: la longueur de liste %2 est négative</translation>
    </message>
    <message>
        <source>%1 has no file extension (expected .obj, .off or .ply)</source>
        <translation>%1 n’a pas d’extension de fichier (.obj, .off ou .ply attendue)</translation>
    </message>
    <message>
        <source>unknown mesh file extension &apos;%1&apos; of %2 (expected .obj, .off or .ply)</source>
        <translation>extension de fichier de maillage inconnue «&#xa0;%1&#xa0;» pour %2 (.obj, .off ou .ply attendue)</translation>
    </message>
    <message>
        <source>cannot open %1</source>
        <translation>impossible d’ouvrir %1</translation>
    </message>
    <message>
        <source>cannot read %1</source>
        <translation>impossible de lire %1</translation>
    </message>
    <message>
        <source>%1: a NUL byte: not a text file</source>
        <translation>%1&#xa0;: un octet NUL&#xa0;: ce n’est pas un fichier texte</translation>
    </message>
    <message>
        <source>the mesh has %1 vertices, but %2 positions were given</source>
        <translation>le maillage a %1 sommets, mais %2 positions ont été données</translation>
    </message>
    <message>
        <source>mesh vertices</source>
        <translation>sommets du maillage</translation>
    </message>
    <message>
        <source>depth %1 makes about %2 points; at most 2^31 are drawn</source>
        <translation>la profondeur %1 donne environ %2 points&#x202f;; 2^31 au plus sont tracés</translation>
    </message>
    <message>
        <source>the mesh has more than %1 kinds of neighbourhood</source>
        <translation>le maillage a plus de %1 types de voisinage</translation>
    </message>
    <message>
        <source>the irregular vertices do not separate</source>
        <translation>les sommets irréguliers ne se séparent pas</translation>
    </message>
    <message>
        <source>vertex %1 has %2 edges; valences above %3 are not supported</source>
        <translation>le sommet %1 a %2 arêtes&#x202f;; les valences supérieures à %3 ne sont pas prises en charge</translation>
    </message>
    <message>
        <source>face %1 has %2 sides; faces of more than %3 sides are not supported</source>
        <translation>la face %1 a %2 côtés&#x202f;; les faces de plus de %3 côtés ne sont pas prises en charge</translation>
    </message>
    <message>
        <source>%1, line %2: the OpenSubdiv tag &apos;t %3&apos; is not applied: this version subdivides without creases, corners, holes or boundary rules, so the surface differs from OpenSubdiv&apos;s where it acts</source>
        <translation type="vanished">%1, ligne %2&#xa0;: l&apos;étiquette OpenSubdiv &apos;t %3&apos; n&apos;est pas appliquée&#xa0;: cette version subdivise sans arêtes vives, coins, trous ni règles de bord, donc la surface diffère de celle d&apos;OpenSubdiv là où elle agit</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 OpenSubdiv tags &apos;t %5&apos; are not applied: this version subdivides without creases, corners, holes or boundary rules, so the surface differs from OpenSubdiv&apos;s where they act</source>
        <translation type="vanished">%1, lignes %2 à %3&#xa0;: %4 étiquettes OpenSubdiv &apos;t %5&apos; ne sont pas appliquées&#xa0;: cette version subdivise sans arêtes vives, coins, trous ni règles de bord, donc la surface diffère de celle d&apos;OpenSubdiv là où elles agissent</translation>
    </message>
    <message>
        <source>%1: UTF-16 text of an odd number of bytes</source>
        <translation>%1&#xa0;: texte UTF-16 d&apos;un nombre impair d&apos;octets</translation>
    </message>
    <message>
        <source>%1: invalid UTF-16 text (a lone surrogate)</source>
        <translation>%1&#xa0;: texte UTF-16 invalide (un substitut isolé)</translation>
    </message>
    <message>
        <source>%1: malformed PLY header line &apos;%2&apos;</source>
        <translation>%1&#xa0;: ligne d&apos;en-tête PLY mal formée &apos;%2&apos;</translation>
    </message>
    <message>
        <source>%1: header line &apos;%2&apos; is not PLY 1.0&apos;s: skipped</source>
        <translation>%1&#xa0;: la ligne d&apos;en-tête &apos;%2&apos; n&apos;est pas du PLY 1.0&#xa0;: ignorée</translation>
    </message>
    <message>
        <source>%1 problems, the first %2: %3</source>
        <translation>%1 problèmes, les %2 premiers&#xa0;: %3</translation>
    </message>
    <message>
        <source>%1 problems: %2</source>
        <translation>%1 problèmes&#xa0;: %2</translation>
    </message>
    <message>
        <source>the ring analysis takes interior valences 3 to 64; this vertex has %1</source>
        <translation>l&apos;analyse de l&apos;anneau prend les valences intérieures de 3 à 64&#xa0;; ce sommet a %1</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 more OpenSubdiv tag lines of other names are not applied either</source>
        <translation>%1, lignes %2 à %3&#xa0;: %4 autres lignes d&apos;étiquettes OpenSubdiv d&apos;autres noms ne sont pas appliquées non plus</translation>
    </message>
    <message>
        <source>%1: %2 header lines that are not PLY 1.0&apos;s, the first &apos;%3&apos;, are skipped</source>
        <translation>%1&#xa0;: %2 lignes d&apos;en-tête qui ne sont pas du PLY 1.0, la première &apos;%3&apos;, sont ignorées</translation>
    </message>
    <message>
        <source>the crease on vertices %1 and %2 has sharpness %3; a sharpness is a number of 0 or more</source>
        <translation>l’arête vive sur les sommets %1 et %2 a une netteté de %3 ; une netteté est un nombre positif ou nul</translation>
    </message>
    <message>
        <source>a crease names vertices %1 and %2, but no edge joins them</source>
        <translation>une arête vive désigne les sommets %1 et %2, mais aucune arête ne les relie</translation>
    </message>
    <message>
        <source>a corner names vertex %1, but the mesh has %2 vertices (0 to %3)</source>
        <translation>un coin désigne le sommet %1, mais le maillage a %2 sommets (de 0 à %3)</translation>
    </message>
    <message>
        <source>the corner at vertex %1 has sharpness %2; a sharpness is a number of 0 or more</source>
        <translation>le coin au sommet %1 a une netteté de %2 ; une netteté est un nombre positif ou nul</translation>
    </message>
    <message>
        <source>a hole names face %1, but the mesh has %2 faces (0 to %3)</source>
        <translation>un trou désigne la face %1, mais le maillage a %2 faces (de 0 à %3)</translation>
    </message>
    <message>
        <source>%1, line %2: the OpenSubdiv tag &apos;t %3&apos; is not applied (this version applies crease, corner, hole, interpolateboundary, creasemethod and smoothtriangles), so the surface differs from OpenSubdiv&apos;s where it acts</source>
        <translation>%1, ligne %2 : la balise OpenSubdiv &apos;t %3&apos; n’est pas appliquée (cette version applique crease, corner, hole, interpolateboundary, creasemethod et smoothtriangles) ; la surface diffère donc de celle d’OpenSubdiv là où cette balise agit</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 OpenSubdiv tags &apos;t %5&apos; are not applied (this version applies crease, corner, hole, interpolateboundary, creasemethod and smoothtriangles), so the surface differs from OpenSubdiv&apos;s where they act</source>
        <translation>%1, lignes %2 à %3 : %4 balises OpenSubdiv &apos;t %5&apos; ne sont pas appliquées (cette version applique crease, corner, hole, interpolateboundary, creasemethod et smoothtriangles) ; la surface diffère donc de celle d’OpenSubdiv là où ces balises agissent</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; needs its counts as ints/floats/strings (like 2/1/0), got &apos;%3&apos;</source>
        <translation>%1 : la balise &apos;t %2&apos; demande le nombre de ses valeurs sous la forme ints/floats/strings (par exemple 2/1/0), reçu « %3 »</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; announces %3 values but has %4</source>
        <translation>%1 : la balise &apos;t %2&apos; annonce %3 valeurs mais en contient %4</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; needs %3</source>
        <translation>%1 : la balise &apos;t %2&apos; demande %3</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; names vertex %3, but the file has %4 vertices (tags count from 0: 0 to %5)</source>
        <translation>%1 : la balise &apos;t %2&apos; désigne le sommet %3, mais le fichier a %4 sommets (les balises numérotent à partir de 0 : de 0 à %5)</translation>
    </message>
    <message>
        <source>%1: the hole names face %2, but the file has %3 faces (0 to %4)</source>
        <translation>%1 : le trou désigne la face %2, mais le fichier a %3 faces (de 0 à %4)</translation>
    </message>
    <message>
        <source>Chaikin&apos;s creases last %1 more levels here; the mesh would have more than %2 faces (use the uniform crease method)</source>
        <translation>les arêtes vives de Chaikin durent ici encore %1 niveaux ; le maillage aurait plus de %2 faces (utilisez la méthode uniforme des arêtes vives)</translation>
    </message>
    <message>
        <source>the semi-sharp features last %1 levels; the mesh would have more than %2 faces before its limit positions can be taken</source>
        <translation>les éléments semi-vifs durent %1 niveaux ; le maillage aurait plus de %2 faces avant que ses positions limites puissent être calculées</translation>
    </message>
    <message>
        <source>pairs of vertices and one sharpness, or one per pair</source>
        <translation>des paires de sommets et une netteté, ou une netteté par paire</translation>
    </message>
    <message>
        <source>vertices and one sharpness, or one per vertex</source>
        <translation>des sommets et une netteté, ou une netteté par sommet</translation>
    </message>
    <message>
        <source>the faces it makes holes</source>
        <translation>les faces dont elle fait des trous</translation>
    </message>
    <message>
        <source>one whole number: 0 none, 1 edge and corner, 2 edge only</source>
        <translation>un nombre entier : 0 aucune, 1 arêtes et coins, 2 arêtes seulement</translation>
    </message>
    <message>
        <source>one word: normal or chaikin</source>
        <translation>un mot : normal ou chaikin</translation>
    </message>
    <message>
        <source>one word: catmark or smooth</source>
        <translation>un mot : catmark ou smooth</translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation> et %1 de plus</translation>
    </message>
    <message>
        <source>%1 faces named a vertex twice in a row and now name it once (faces %2)</source>
        <translation>%1 faces nommaient un sommet deux fois de suite et ne le nomment plus qu&apos;une fois (faces %2)</translation>
    </message>
    <message>
        <source>%1 faces were left with fewer than three vertices and were removed (faces %2; the later faces move up)</source>
        <translation>%1 faces avaient moins de trois sommets et ont été supprimées (faces %2 ; les faces suivantes remontent)</translation>
    </message>
    <message>
        <source>%1 boundary vertices at the position of another were welded into it (vertices %2; they stay, used by no face)</source>
        <translation>%1 sommets de bord à la position d&apos;un autre y ont été soudés (sommets %2 ; ils restent, utilisés par aucune face)</translation>
    </message>
    <message>
        <source>%1 faces were turned over to the orientation of the surface they belong to (faces %2)</source>
        <translation>%1 faces ont été retournées selon l&apos;orientation de la surface à laquelle elles appartiennent (faces %2)</translation>
    </message>
    <message>
        <source>the surface of face %1 cannot be oriented (it is a Möbius band or contains one): left as it is</source>
        <translation>la surface de la face %1 n&apos;est pas orientable (c&apos;est un ruban de Möbius ou elle en contient un) : laissée telle quelle</translation>
    </message>
    <message>
        <source>%1 vertices whose faces formed several fans were split, one vertex per fan (vertices %2; the %3 new vertices are numbered from %4)</source>
        <translation>%1 sommets dont les faces formaient plusieurs éventails ont été scindés, un sommet par éventail (sommets %2 ; les %3 nouveaux sommets sont numérotés à partir de %4)</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <translation>(%1, %2)</translation>
    </message>
    <message>
        <source>%1 edges join three or more faces (%2): no choice of sheets is canonical, so they are not repaired</source>
        <translation type="vanished">%1 arêtes joignent trois faces ou plus (%2) : aucun choix de feuillets n&apos;est canonique, elles ne sont donc pas réparées</translation>
    </message>
    <message>
        <source>%1 edges join three or more faces (%2): no choice of sheets is canonical, so they are not repaired; they are drawn as OpenSubdiv draws them, as infinitely sharp creases</source>
        <translation>%1 arêtes joignent trois faces ou plus (%2) : aucun choix de nappes n’est canonique, elles ne sont donc pas réparées ; elles sont dessinées comme OpenSubdiv les dessine, en plis infiniment vifs</translation>
    </message>
    <message>
        <source>%1(%2, %3)</source>
        <translation>%1(%2, %3)</translation>
    </message>
    <message>
        <source>the vertices as corners</source>
        <translation>les sommets en coins</translation>
    </message>
    <message>
        <source>%1 of the vertices as corners, the others on the creases</source>
        <translation>%1 des sommets en coins, les autres sur les plis</translation>
    </message>
    <message>
        <source>non-manifold: %1 vertices (%2), drawn as OpenSubdiv draws them: %3</source>
        <translation>non variété : %1 sommets (%2), dessinés comme OpenSubdiv les dessine : %3</translation>
    </message>
    <message>
        <source>non-manifold: %1 edges (%2) and %3 vertices (%4), drawn as OpenSubdiv draws them: the edges as infinitely sharp creases, %5</source>
        <translation>non variété : %1 arêtes (%2) et %3 sommets (%4), dessinés comme OpenSubdiv les dessine : les arêtes en plis infiniment vifs, %5</translation>
    </message>
    <message>
        <source>its largest eigenvalues below 1 are not real and positive</source>
        <translation>ses plus grandes valeurs propres inférieures à 1 ne sont pas réelles et positives</translation>
    </message>
    <message>
        <source>%1 is a defective eigenvalue (a Jordan block) among the two largest: Reif&apos;s criterion takes them diagonalizable (not decided)</source>
        <translation type="vanished">%1 est une valeur propre défective (un bloc de Jordan) parmi les deux plus grandes : le critère de Reif les suppose diagonalisables (non décidé)</translation>
    </message>
    <message>
        <source>lambda2 = lambda3 = %1: the tangent plane is not determined by the two largest</source>
        <translation>lambda2 = lambda3 = %1 : le plan tangent n’est pas déterminé par les deux plus grandes</translation>
    </message>
    <message>
        <source>its characteristic map is not regular</source>
        <translation>son application caractéristique n’est pas régulière</translation>
    </message>
    <message>
        <source>its characteristic map is not injective</source>
        <translation>son application caractéristique n’est pas injective</translation>
    </message>
    <message>
        <source>%1: %2 crease tags name an edge tagged before (the first: %3 %4): each edge keeps its last sharpness, as OpenSubdiv applies them</source>
        <translation>%1 : %2 étiquettes de pli nomment une arête déjà étiquetée (la première : %3 %4) : chaque arête garde sa dernière netteté, comme OpenSubdiv les applique</translation>
    </message>
    <message>
        <source>%1: %2 corner tags name a vertex tagged before (the first: %3): each vertex keeps its last sharpness, as OpenSubdiv applies them</source>
        <translation>%1 : %2 étiquettes de coin nomment un sommet déjà étiqueté (le premier : %3) : chaque sommet garde sa dernière netteté, comme OpenSubdiv les applique</translation>
    </message>
    <message>
        <source>%1: %2 hole tags name a face made a hole before</source>
        <translation>%1 : %2 étiquettes de trou nomment une face déjà trouée</translation>
    </message>
    <message>
        <source>lambda1 = lambda2 = %1 is a Jordan block: the rings shear, and Reif&apos;s criterion holds for the map of its eigenvector and generalized eigenvector</source>
        <translation>lambda1 = lambda2 = %1 est un bloc de Jordan : les anneaux se cisaillent, et le critère de Reif vaut pour l&apos;application de son vecteur propre et de son vecteur propre généralisé</translation>
    </message>
    <message>
        <source>lambda1 = lambda2 = %1 has two eigenvectors and a Jordan chain: the normal and the rings follow the map of the two eigenvectors</source>
        <translation>lambda1 = lambda2 = %1 a deux vecteurs propres et une chaîne de Jordan : la normale et les anneaux suivent l&apos;application des deux vecteurs propres</translation>
    </message>
    <message>
        <source>lambda2 = %1 is a Jordan block: its chain&apos;s top term k lambda2^k dominates, and Reif&apos;s criterion holds for the map of the eigenvectors of lambda1 and of the chain&apos;s top</source>
        <translation>lambda2 = %1 est un bloc de Jordan : le terme k lambda2^k du sommet de sa chaîne domine, et le critère de Reif vaut pour l&apos;application des vecteurs propres de lambda1 et du sommet de la chaîne</translation>
    </message>
    <message>
        <source>%1 is a defective eigenvalue with a Jordan chain longer than two, or more than one chain: Reif&apos;s criterion is not decided there</source>
        <translation>%1 est une valeur propre défective avec une chaîne de Jordan de longueur supérieure à deux, ou plusieurs chaînes : le critère de Reif n&apos;y est pas décidé</translation>
    </message>
    <message>
        <source>the eigenvectors of lambda1 and lambda2 vanish on the crease of edge %1, whose own tangent (a smaller eigenvalue) leaves their tangent plane: not C1 for generic data</source>
        <translation>les vecteurs propres de lambda1 et lambda2 s’annulent sur l’arête vive %1, dont la tangente propre (une valeur propre plus petite) sort de leur plan tangent : pas C1 pour des données génériques</translation>
    </message>
</context>
<context>
    <name>awb::render</name>
    <message>
        <source>raster size must be between 1x1 and 32768x32768, got %1x%2</source>
        <translation>la taille de la trame doit être comprise entre 1x1 et 32768x32768 (reçu&#xa0;: %1x%2)</translation>
    </message>
    <message>
        <source>supersampling must be 1 to 4 cells per pixel side, got %1</source>
        <translation>le suréchantillonnage doit être de 1 à 4 cellules par côté de pixel (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the supersampled raster would hold more than 1.2e9 cells</source>
        <translation>la trame suréchantillonnée contiendrait plus de 1,2e9 cellules</translation>
    </message>
    <message>
        <source>raster world rectangle is empty or not finite</source>
        <translation>le rectangle du monde de la trame est vide ou non fini</translation>
    </message>
    <message>
        <source>cannot merge density images of different sizes or modes</source>
        <translation>impossible de fusionner des images de densité de tailles ou de modes différents</translation>
    </message>
    <message>
        <source>density image does not match its frame</source>
        <translation>l’image de densité ne correspond pas à son cadre</translation>
    </message>
    <message>
        <source>a view does not fit the IFS space</source>
        <translation>une vue ne correspond pas à l’espace de l’IFS</translation>
    </message>
    <message>
        <source>there is no IFS to draw</source>
        <translation>il n’y a aucun IFS à tracer</translation>
    </message>
    <message>
        <source>the IFS has no view to draw it with</source>
        <translation>l’IFS n’a aucune vue avec laquelle le tracer</translation>
    </message>
    <message>
        <source>the colour table does not cover the address labels</source>
        <translation>la table des couleurs ne couvre pas les étiquettes d’adresse</translation>
    </message>
</context>
<context>
    <name>awb::schemes</name>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1 = %2 &lt; 1</source>
        <translation>%1 = %2 &lt; 1</translation>
    </message>
    <message>
        <source>%1 = %2: on the circle %1 = 1, so %3 is an isometry, not a contraction</source>
        <translation>%1 = %2&#xa0;: sur le cercle %1 = 1, donc %3 est une isométrie, pas une contraction</translation>
    </message>
    <message>
        <source>%1 = %2 &gt; 1, so %3 expands</source>
        <translation>%1 = %2 &gt; 1, donc %3 est dilatante</translation>
    </message>
    <message>
        <source>y must be a finite nonzero number (t = 1/2 + i y)</source>
        <translation>y doit être un nombre fini non nul (t = 1/2 + i y)</translation>
    </message>
    <message>
        <source>t = 1/2 + i y with y = %1: %2</source>
        <translation>t = 1/2 + i y avec y = %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>depth must be between 1 and 24, got %1</source>
        <translation>la profondeur doit être comprise entre 1 et 24 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the subdivision parameter t</source>
        <translation>le paramètre de subdivision t</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies inside both discs: the IFS is hyperbolic (contraction factor %4) and its attractor is a connected curve (Theorem 3.7.2)</source>
        <translation>t = %1&#xa0;: %2, %3. t est à l’intérieur des deux disques&#xa0;: l’IFS est hyperbolique (facteur de contraction %4) et son attracteur est une courbe connexe (théorème 3.7.2)</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies outside both discs |t| &lt; 1 and |1 - t| &lt; 1: the IFS is not hyperbolic and has no attractor</source>
        <translation>t = %1&#xa0;: %2, %3. t est à l’extérieur des deux disques |t| &lt; 1 et |1 - t| &lt; 1&#xa0;: l’IFS n’est pas hyperbolique et n’a pas d’attracteur</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies outside the disc %4: the IFS is not hyperbolic and has no attractor</source>
        <translation>t = %1&#xa0;: %2, %3. t est à l’extérieur du disque %4&#xa0;: l’IFS n’est pas hyperbolique et n’a pas d’attracteur</translation>
    </message>
    <message>
        <source>a Bézier curve needs at least 2 control points (degree &gt;= 1), got %1</source>
        <translation>une courbe de Bézier demande au moins 2 points de contrôle (degré &gt;= 1) (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>control points</source>
        <translation>points de contrôle</translation>
    </message>
    <message>
        <source>all control points coincide: the curve is a single point and the lifted matrix of 000 §2 is singular</source>
        <translation>tous les points de contrôle sont confondus&#xa0;: la courbe est réduite à un point et la matrice relevée de 000 §2 est singulière</translation>
    </message>
    <message>
        <source>depth must be between 0 and 24, got %1</source>
        <translation>la profondeur doit être comprise entre 0 et 24 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the Takagi function needs a finite x</source>
        <translation>la fonction de Takagi demande un x fini</translation>
    </message>
    <message>
        <source>the number of Takagi terms must be &gt;= 0</source>
        <translation>le nombre de termes de Takagi doit être &gt;= 0</translation>
    </message>
    <message>
        <source>binary codes longer than 60 digits are not supported</source>
        <translation>les codes binaires de plus de 60 chiffres ne sont pas pris en charge</translation>
    </message>
    <message>
        <source>a binary code has digits 0 and 1 only (digit %1 is %2)</source>
        <translation>un code binaire ne contient que les chiffres 0 et 1 (le chiffre %1 vaut %2)</translation>
    </message>
    <message>
        <source>Takagi image: needs at least 2 control points, got %1</source>
        <translation>image de Takagi&#xa0;: il faut au moins 2 points de contrôle (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>Takagi image: control points and y must be finite</source>
        <translation>image de Takagi&#xa0;: les points de contrôle et y doivent être finis</translation>
    </message>
    <message>
        <source>Takagi image: depth %1 is outside 1..20</source>
        <translation>image de Takagi&#xa0;: la profondeur %1 est hors de 1..20</translation>
    </message>
    <message>
        <source>control points must have 2 or 3 coordinates, got %1</source>
        <translation>les points de contrôle doivent avoir 2 ou 3 coordonnées (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>%1 control points are too few: affine combinations in %2D need at least %3 that are not collinear</source>
        <translation>%1 points de contrôle, c’est trop peu&#xa0;: les combinaisons affines en %2D demandent au moins %3 points non alignés</translation>
    </message>
    <message>
        <source>%1 control points are too few: affine combinations in %2D need at least %3 that are not coplanar</source>
        <translation>%1 points de contrôle, c’est trop peu&#xa0;: les combinaisons affines en %2D demandent au moins %3 points non coplanaires</translation>
    </message>
    <message>
        <source>the control points are all collinear: they must span the plane to write every image point as their affine combination (000 eq. (5))</source>
        <translation>les points de contrôle sont tous alignés&#xa0;: ils doivent engendrer le plan pour que tout point image s’écrive comme leur combinaison affine (000 éq. (5))</translation>
    </message>
    <message>
        <source>the control points are all coplanar: they must span space to write every image point as their affine combination (000 eq. (5))</source>
        <translation>les points de contrôle sont tous coplanaires&#xa0;: ils doivent engendrer l’espace pour que tout point image s’écrive comme leur combinaison affine (000 éq. (5))</translation>
    </message>
    <message>
        <source>the point has %1 coordinates, the control points have %2</source>
        <translation>le point a %1 coordonnées, les points de contrôle en ont %2</translation>
    </message>
    <message>
        <source>point</source>
        <translation>point</translation>
    </message>
    <message>
        <source>the IFS has no maps</source>
        <translation>l’IFS n’a aucune application</translation>
    </message>
    <message>
        <source>map f_%1 is not a map of %2D points like the control points</source>
        <translation>l’application f_%1 n’est pas une application de points %2D comme les points de contrôle</translation>
    </message>
    <message>
        <source>map f_%1 (linear part)</source>
        <translation>application f_%1 (partie linéaire)</translation>
    </message>
    <message>
        <source>map f_%1 (translation)</source>
        <translation>application f_%1 (translation)</translation>
    </message>
    <message>
        <source>Koch curve with control points</source>
        <translation>Courbe de Koch à points de contrôle</translation>
    </message>
    <message>
        <source>Sierpinski gasket with control points</source>
        <translation>Triangle de Sierpinski à points de contrôle</translation>
    </message>
    <message>
        <source>%1 needs %2 control points in the plane, got %3 with %4 coordinates</source>
        <translation>%1 demande %2 points de contrôle dans le plan (reçu&#xa0;: %3 points à %4 coordonnées)</translation>
    </message>
    <message>
        <source>Bézier degree must be at least 1</source>
        <translation>le degré d’une courbe de Bézier doit être au moins 1</translation>
    </message>
    <message>
        <source>B-spline degree must be at least 1</source>
        <translation>le degré d’une B-spline doit être au moins 1</translation>
    </message>
    <message>
        <source>a B-spline of degree %1 needs at least %2 control points (%3 knots), got %4 knots</source>
        <translation>une B-spline de degré %1 demande au moins %2 points de contrôle (%3 nœuds) (reçu&#xa0;: %4 nœuds)</translation>
    </message>
    <message>
        <source>B-spline knot %1 is not a finite number</source>
        <translation>le nœud %1 de la B-spline n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>B-spline knots must be nondecreasing (knot %1)</source>
        <translation>les nœuds de la B-spline doivent être croissants au sens large (nœud %1)</translation>
    </message>
    <message>
        <source>B-spline knot vector has an empty domain</source>
        <translation>le vecteur nodal de la B-spline a un domaine vide</translation>
    </message>
    <message>
        <source>an end-interpolating B-spline of degree %1 needs at least %2 control points</source>
        <translation>une B-spline interpolant les extrémités de degré %1 demande au moins %2 points de contrôle</translation>
    </message>
    <message>
        <source>B-spline needs %1 control points, got %2</source>
        <translation>la B-spline demande %1 points de contrôle (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>scheme %1: the dilation must be at least 2</source>
        <translation>schéma %1&#xa0;: la dilatation doit être au moins 2</translation>
    </message>
    <message>
        <source>scheme %1: the mask holds a non-finite weight</source>
        <translation>schéma %1&#xa0;: le masque contient un poids non fini</translation>
    </message>
    <message>
        <source>scheme %1: the mask is empty</source>
        <translation>schéma %1&#xa0;: le masque est vide</translation>
    </message>
    <message>
        <source>scheme %1: the mask entries of class (%2, %3) mod %4 sum to %5, not 1</source>
        <translation>schéma %1&#xa0;: les coefficients du masque de la classe (%2, %3) mod %4 ont pour somme %5, et non 1</translation>
    </message>
    <message>
        <source>scheme %1: local subdivision matrix not closed</source>
        <translation>schéma %1&#xa0;: matrice de subdivision locale non fermée</translation>
    </message>
    <message>
        <source>scheme %1: the local subdivision matrix has no eigenvalue 1</source>
        <translation>schéma %1&#xa0;: la matrice de subdivision locale n’a pas la valeur propre 1</translation>
    </message>
    <message>
        <source>scheme %1: the limit eigenvector sums to 0</source>
        <translation>schéma %1&#xa0;: la somme des composantes du vecteur propre limite est nulle</translation>
    </message>
    <message>
        <source>box spline %1: its directions sum to an odd vector, so the mask has no lattice-point centre</source>
        <translation>box-spline %1&#xa0;: la somme de ses directions est un vecteur impair, donc le masque n’a pas de centre sur un point de la grille</translation>
    </message>
    <message>
        <source>bicubic B-spline</source>
        <translation>B-spline bicubique</translation>
    </message>
    <message>
        <source>Loop (three-direction quartic box spline)</source>
        <translation>Loop (box-spline quartique à trois directions)</translation>
    </message>
    <message>
        <source>Kobbelt √3 (two rounds)</source>
        <translation>Kobbelt √3 (deux passes)</translation>
    </message>
    <message>
        <source>positive (edge rotated 90° counter-clockwise)</source>
        <translation>positive (arête tournée de 90° dans le sens trigonométrique)</translation>
    </message>
    <message>
        <source>negative (edge rotated 90° clockwise)</source>
        <translation>négative (arête tournée de 90° dans le sens horaire)</translation>
    </message>
    <message>
        <source>constant</source>
        <comment>β sign</comment>
        <translation>constant</translation>
    </message>
    <message>
        <source>Positive normal: the edge vector P_i P_{i+1} rotated 90° counter-clockwise; negative: rotated clockwise. d_i = |P_i P_{i+1}| n_i. In the β signs (-1)^i, (-1)^(k+i), (-1)^(k+1), k is the level of the polygon being subdivided (the first step has k = 0) and i the 0-based index of the edge.</source>
        <translation>Normale positive&#xa0;: le vecteur d’arête P_i P_{i+1} tourné de 90° dans le sens trigonométrique&#x202f;; négative&#xa0;: tourné dans le sens horaire. d_i = |P_i P_{i+1}| n_i. Dans les signes de β (-1)^i, (-1)^(k+i), (-1)^(k+1), k est le niveau du polygone en cours de subdivision (la première étape a k = 0) et i l’indice de l’arête, numérotée à partir de 0.</translation>
    </message>
    <message>
        <source>p = %1: the normal-vector scheme needs p &gt;= 2 rules, one (α_j, β_j) pair each</source>
        <translation>p = %1&#xa0;: le schéma à vecteurs normaux demande p &gt;= 2 règles, chacune avec une paire (α_j, β_j)</translation>
    </message>
    <message>
        <source>β has %1 values but α has %2: eq. (1) needs one (α_j, β_j) pair per rule j = 0..p-1</source>
        <translation>β a %1 valeurs mais α en a %2&#xa0;: l’éq. (1) demande une paire (α_j, β_j) par règle j = 0..p-1</translation>
    </message>
    <message>
        <source>α_%1 is not a finite number</source>
        <translation>α_%1 n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>β_%1 is not a finite number</source>
        <translation>β_%1 n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1 β signs given for p = %2 rules: give none, one for all rules, or one per rule</source>
        <translation>%1 signes de β donnés pour p = %2 règles&#xa0;: n’en donnez aucun, un pour toutes les règles, ou un par règle</translation>
    </message>
    <message>
        <source>p = %1, α = %2, β = %3, β signs (%4), normals %5</source>
        <translation>p = %1, α = %2, β = %3, signes de β (%4), normales %5</translation>
    </message>
    <message>
        <source>the normal-vector scheme works in the plane: control points need 2 coordinates, got %1</source>
        <translation>le schéma à vecteurs normaux travaille dans le plan&#xa0;: les points de contrôle doivent avoir 2 coordonnées (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>control polygon</source>
        <translation>polygone de contrôle</translation>
    </message>
    <message>
        <source>a closed control polygon needs at least %1 points, got %2</source>
        <translation>un polygone de contrôle fermé demande au moins %1 points (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>an open control polygon needs at least %1 points, got %2</source>
        <translation>un polygone de contrôle ouvert demande au moins %1 points (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>open control polygons need α_0 = β_0 = 0: rule 0 at the last point (i = p^k n in eq. (1)) would use a point after the end; close the polygon instead</source>
        <translation>les polygones de contrôle ouverts exigent α_0 = β_0 = 0&#xa0;: la règle 0 au dernier point (i = p^k n dans l’éq. (1)) utiliserait un point situé après la fin&#x202f;; fermez plutôt le polygone</translation>
    </message>
    <message>
        <source>the number of subdivision steps cannot be negative, got %1</source>
        <translation>le nombre d’étapes de subdivision ne peut pas être négatif (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the subdivision level cannot be negative, got %1</source>
        <translation>le niveau de subdivision ne peut pas être négatif (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>%1 subdivision steps of a polygon with %2 edges would make %3 points (at most %4); use fewer steps</source>
        <translation>%1 étapes de subdivision d’un polygone à %2 arêtes produiraient %3 points (au plus %4)&#x202f;; utilisez moins d’étapes</translation>
    </message>
    <message>
        <source>convergent: every edge shrinks by a factor of at most %1 per step, so ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (longest initial edge) and F^k is a Cauchy sequence (the argument of 001 Theorem 1); non-rectifiable: the polygon length grows by a factor of at least %3 per step (001 Theorem 2)</source>
        <translation>convergent&#xa0;: chaque arête rétrécit d’un facteur d’au plus %1 par étape, donc ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (plus longue arête initiale) et F^k est une suite de Cauchy (l’argument du théorème 1 de 001)&#x202f;; non rectifiable&#xa0;: la longueur du polygone croît d’un facteur d’au moins %3 par étape (théorème 2 de 001)</translation>
    </message>
    <message>
        <source>convergent: every edge shrinks by a factor of at most %1 per step, so ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (longest initial edge) and F^k is a Cauchy sequence (the argument of 001 Theorem 1)</source>
        <translation>convergent&#xa0;: chaque arête rétrécit d’un facteur d’au plus %1 par étape, donc ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (plus longue arête initiale) et F^k est une suite de Cauchy (l’argument du théorème 1 de 001)</translation>
    </message>
    <message>
        <source>not decided: the one-step edge bound is %1 &gt;= 1, so the argument of 001 Theorem 1 does not apply (see the measured edge lengths per level)</source>
        <translation>non décidé&#xa0;: la borne sur les arêtes en une étape vaut %1 &gt;= 1, donc l’argument du théorème 1 de 001 ne s’applique pas (voir les longueurs d’arêtes mesurées par niveau)</translation>
    </message>
    <message>
        <source>α_0 and β_0 are not both 0: the new edge across each old vertex joins two old edges and is not the image of one edge, so no IFS of one similarity per new edge exists</source>
        <translation>α_0 et β_0 ne sont pas tous deux nuls&#xa0;: la nouvelle arête qui traverse chaque ancien sommet relie deux anciennes arêtes et n’est pas l’image d’une seule arête, donc il n’existe pas d’IFS à une similitude par nouvelle arête</translation>
    </message>
    <message>
        <source>new edge %1 of the unit edge has length %2 &gt;= 1: no map would contract</source>
        <translation>la nouvelle arête %1 de l’arête unité a pour longueur %2 &gt;= 1&#xa0;: aucune application ne serait contractante</translation>
    </message>
    <message>
        <source>no IFS of %1 similarities (each new edge taken forward or reversed, plain or mirrored: %2 patterns) reproduces the polygons of the first %3 steps; the β sign changes with the level, so the rules repeat only every two steps (an IFS would need p^2 maps)</source>
        <translation>aucun IFS de %1 similitudes (chaque nouvelle arête parcourue dans un sens ou dans l’autre, telle quelle ou en miroir&#xa0;: %2 combinaisons) ne reproduit les polygones des %3 premières étapes&#x202f;; le signe de β change avec le niveau, donc les règles ne se répètent que toutes les deux étapes (un IFS demanderait p^2 applications)</translation>
    </message>
    <message>
        <source>no IFS of %1 similarities (each new edge taken forward or reversed, plain or mirrored: %2 patterns) reproduces the polygons of the first %3 steps</source>
        <translation>aucun IFS de %1 similitudes (chaque nouvelle arête parcourue dans un sens ou dans l’autre, telle quelle ou en miroir&#xa0;: %2 combinaisons) ne reproduit les polygones des %3 premières étapes</translation>
    </message>
    <message>
        <source>no equivalent IFS: %1</source>
        <translation>pas d’IFS équivalent&#xa0;: %1</translation>
    </message>
    <message>
        <source>edge %1 of the control polygon is subdivided with rules no similarity copy of the unit edge&apos;s limit reproduces</source>
        <translation>l’arête %1 du polygone de contrôle est subdivisée avec des règles qu’aucune copie semblable de la limite de l’arête unité ne reproduit</translation>
    </message>
    <message>
        <source>Lévy C curve</source>
        <translation>Courbe C de Lévy</translation>
    </message>
    <message>
        <source>binary interpolatory; new point at the apex of a right isosceles triangle</source>
        <translation>binaire interpolant&#x202f;; nouveau point au sommet d’un triangle rectangle isocèle</translation>
    </message>
    <message>
        <source>Dragon curve</source>
        <translation>Courbe du dragon</translation>
    </message>
    <message>
        <source>scheme (2) with β_1 = (-1)^i / 2: the bump alternates sides along the curve</source>
        <translation>schéma (2) avec β_1 = (-1)^i / 2&#xa0;: la bosse change de côté le long de la courbe</translation>
    </message>
    <message>
        <source>Sierpiński gasket (arrowhead curve)</source>
        <translation>Triangle de Sierpiński (courbe en pointe de flèche)</translation>
    </message>
    <message>
        <source>non-stationary and non-uniform, as in the paper: β_1 = β_2 = (-1)^(k+i) √3/4 flips with the level k and the edge i; the polygons tend to the gasket</source>
        <translation>non stationnaire et non uniforme, comme dans l’article&#xa0;: β_1 = β_2 = (-1)^(k+i) √3/4 change de signe avec le niveau k et l’arête i&#x202f;; les polygones tendent vers le triangle de Sierpiński</translation>
    </message>
    <message>
        <source>Koch curve</source>
        <translation>Courbe de Koch</translation>
    </message>
    <message>
        <source>quaternary interpolatory; the limit is the classic Koch curve</source>
        <translation>quaternaire interpolant&#x202f;; la limite est la courbe de Koch classique</translation>
    </message>
    <message>
        <source>Koch snowflake</source>
        <translation>Flocon de Koch</translation>
    </message>
    <message>
        <source>the triangle traversed counter-clockwise with negative normals, so every bump points outwards (NOTES.md)</source>
        <translation>le triangle parcouru dans le sens trigonométrique avec des normales négatives, de sorte que chaque bosse pointe vers l’extérieur (NOTES.md)</translation>
    </message>
    <message>
        <source>Tigerhead-like curve</source>
        <translation>Courbe en tête de tigre</translation>
    </message>
    <message>
        <source>α = (0, -1/4, 1/2, 5/4), β = (0, 1/3, 1/2, 1/3): rules 1 and 3 lie outside the edge, so the curve overlaps itself</source>
        <translation>α = (0, -1/4, 1/2, 5/4), β = (0, 1/3, 1/2, 1/3)&#xa0;: les règles 1 et 3 tombent hors de l’arête, donc la courbe se recouvre elle-même</translation>
    </message>
    <message>
        <source>Human-like curve</source>
        <translation>Courbe humanoïde</translation>
    </message>
    <message>
        <source>β = (-1)^(k+1) (0, 1/3, 1/2, 1/3): the bumps point down at the first step (k = 0) and flip at every level</source>
        <translation>β = (-1)^(k+1) (0, 1/3, 1/2, 1/3)&#xa0;: les bosses pointent vers le bas à la première étape (k = 0) et s’inversent à chaque niveau</translation>
    </message>
    <message>
        <source>Approximating curve</source>
        <translation>Courbe approximante</translation>
    </message>
    <message>
        <source>α_0 = -1/2 moves the old points, so the polygon must be closed; the text does not give the quadrilateral of Fig. 3(c): a unit square traversed counter-clockwise is assumed</source>
        <translation>α_0 = -1/2 déplace les anciens points, donc le polygone doit être fermé&#x202f;; le texte ne donne pas le quadrilatère de la fig. 3(c)&#xa0;: on suppose un carré unité parcouru dans le sens trigonométrique</translation>
    </message>
    <message>
        <source>Crown-like curve</source>
        <translation>Courbe en couronne</translation>
    </message>
    <message>
        <source>6-ary interpolatory</source>
        <translation>6-aire interpolant</translation>
    </message>
    <message>
        <source>7-ary square-wave curve</source>
        <translation>Courbe en créneaux 7-aire</translation>
    </message>
    <message>
        <source>the paper calls it the Minkowski curve; it equals the Minkowski sausage only at level 1 (its middle edge has length 1/2 and is replaced by a half-size copy), so it is a different curve of similarity dimension log_2 3, not 1.5</source>
        <translation>l’article l’appelle courbe de Minkowski&#x202f;; elle ne coïncide avec la saucisse de Minkowski qu’au niveau 1 (son arête centrale a pour longueur 1/2 et est remplacée par une copie de taille moitié)&#xa0;: c’est donc une autre courbe, de dimension de similitude log_2 3, et non 1,5</translation>
    </message>
    <message>
        <source>unknown normal-vector preset %1</source>
        <translation>préréglage à vecteurs normaux %1 inconnu</translation>
    </message>
    <message>
        <source>%1 needs exactly %2 control points, got %3</source>
        <translation>%1 demande exactement %2 points de contrôle (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>%1 needs at least %2 control points, got %3</source>
        <translation>%1 demande au moins %2 points de contrôle (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>%1: the arity of a scheme must be at least 2, got %2</source>
        <translation>%1&#xa0;: l’arité d’un schéma doit être au moins 2 (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>%1: a scheme of arity %2 needs %2 rules, got %3</source>
        <translation>%1&#xa0;: un schéma d’arité %2 demande %2 règles (reçu&#xa0;: %3)</translation>
    </message>
    <message>
        <source>%1: rule %2 has no weights</source>
        <translation>%1&#xa0;: la règle %2 n’a pas de poids</translation>
    </message>
    <message>
        <source>%1: weight %2 of rule %3 is not a finite number</source>
        <translation>%1&#xa0;: le poids %2 de la règle %3 n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>%1: the weights of rule %2 sum to %3, not 1 (an affine rule must reproduce constants)</source>
        <translation>%1&#xa0;: la somme des poids de la règle %2 vaut %3, et non 1 (une règle affine doit reproduire les constantes)</translation>
    </message>
    <message>
        <source>B-spline degree must be between 1 and 15, got %1</source>
        <translation>le degré de la B-spline doit être compris entre 1 et 15 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>uniform B-spline of degree %1</source>
        <translation>B-spline uniforme de degré %1</translation>
    </message>
    <message>
        <source>corner cutting needs 0 &lt; a &lt; b &lt; 1, got a = %1, b = %2</source>
        <translation>la découpe de coins demande 0 &lt; a &lt; b &lt; 1 (reçu&#xa0;: a = %1, b = %2)</translation>
    </message>
    <message>
        <source>corner cutting (%1, %2)</source>
        <translation>découpe de coins (%1, %2)</translation>
    </message>
    <message>
        <source>four-point tension omega is not a finite number</source>
        <translation>la tension oméga du schéma à quatre points n’est pas un nombre fini</translation>
    </message>
    <message>
        <source>four-point (omega = %1)</source>
        <translation>schéma à quatre points (oméga = %1)</translation>
    </message>
    <message>
        <source>Bézier degree must be between 1 and 30, got %1</source>
        <translation>le degré de Bézier doit être compris entre 1 et 30 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the de Casteljau split parameter t must lie strictly between 0 and 1, got %1</source>
        <translation>le paramètre de découpe de de Casteljau t doit être strictement compris entre 0 et 1 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>Bézier of degree %1 (de Casteljau at t = %2)</source>
        <translation>Bézier de degré %1 (de Casteljau en t = %2)</translation>
    </message>
    <message>
        <source>end-interpolating B-spline of degree %1</source>
        <translation>B-spline interpolant les extrémités de degré %1</translation>
    </message>
    <message>
        <source>%1: an IFS needs at least two matrices, got %2</source>
        <translation>%1&#xa0;: un IFS demande au moins deux matrices (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>%1: matrix S_1 is empty</source>
        <translation>%1&#xa0;: la matrice S_1 est vide</translation>
    </message>
    <message>
        <source>%1: matrix S_%2 is %3 x %4, expected %5 x %5 like S_1</source>
        <translation>%1&#xa0;: la matrice S_%2 est de taille %3 x %4, %5 x %5 attendu comme pour S_1</translation>
    </message>
    <message>
        <source>%1: matrix S_%2</source>
        <translation>%1&#xa0;: matrice S_%2</translation>
    </message>
    <message>
        <source>%1: matrix S_%2, row %3 sums to %4, not 1 (subdivision rows are affine combinations)</source>
        <translation>%1&#xa0;: matrice S_%2, la somme de la ligne %3 vaut %4, et non 1 (les lignes de subdivision sont des combinaisons affines)</translation>
    </message>
    <message>
        <source>the number of subdivision steps cannot be negative</source>
        <translation>le nombre d’étapes de subdivision ne peut pas être négatif</translation>
    </message>
    <message>
        <source>classic subdivision with %1 steps would make %2 points; use fewer steps</source>
        <translation>une subdivision classique de %1 étapes produirait %2 points&#x202f;; utilisez moins d’étapes</translation>
    </message>
    <message>
        <source>user matrices</source>
        <translation>matrices utilisateur</translation>
    </message>
    <message>
        <source>the square lattice of %1 has no layout &apos;%2&apos; (it has: %3)</source>
        <translation>la grille carrée de %1 n’a pas de disposition «&#xa0;%2&#xa0;» (dispositions disponibles&#xa0;: %3)</translation>
    </message>
    <message>
        <source>the triangular lattice of %1 has no layout &apos;%2&apos; (it has: %3)</source>
        <translation>la grille triangulaire de %1 n’a pas de disposition «&#xa0;%2&#xa0;» (dispositions disponibles&#xa0;: %3)</translation>
    </message>
    <message>
        <source>%1: the mask is not symmetric under the turn of map %2 of the %3 layout</source>
        <translation>%1&#xa0;: le masque n’est pas symétrique pour la rotation de l’application %2 de la disposition %3</translation>
    </message>
    <message>
        <source>%1: the pieces of the %2 layout are not determined by a finite net</source>
        <translation>%1&#xa0;: les morceaux de la disposition %2 ne sont pas déterminés par un réseau fini</translation>
    </message>
    <message>
        <source>the patch needs %1 control points on its net, got %2</source>
        <translation>le carreau demande %1 points de contrôle sur son réseau (reçu&#xa0;: %2)</translation>
    </message>
    <message>
        <source>lattice point %1 is given twice (points %2 and %3)</source>
        <translation>le point de grille %1 est donné deux fois (points %2 et %3)</translation>
    </message>
    <message>
        <source>lattice point %1 (point %2) is not on the square net of the patch; missing: %3</source>
        <translation>le point de grille %1 (point %2) n’est pas sur le réseau carré du carreau&#x202f;; manquants&#xa0;: %3</translation>
    </message>
    <message>
        <source>lattice point %1 (point %2) is not on the triangular net of the patch; missing: %3</source>
        <translation>le point de grille %1 (point %2) n’est pas sur le réseau triangulaire du carreau&#x202f;; manquants&#xa0;: %3</translation>
    </message>
    <message>
        <source>the net has %1 lattice points but %2 control points</source>
        <translation>le réseau a %1 points de grille mais %2 points de contrôle</translation>
    </message>
    <message>
        <source>refinement rounds must be from 0 to 12, got %1</source>
        <translation>le nombre de passes de raffinement doit être compris entre 0 et 12 (reçu&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the mesh was refined by another scheme</source>
        <translation>le maillage a été raffiné par un autre schéma</translation>
    </message>
    <message>
        <source>the arity of a mask must be between 2 and 64, got %1</source>
        <translation>l&apos;arité d&apos;un masque doit être comprise entre 2 et 64 (valeur reçue&#xa0;: %1)</translation>
    </message>
    <message>
        <source>a mask needs between 1 and 4096 coefficients, got %1</source>
        <translation>un masque nécessite entre 1 et 4096 coefficients (valeur reçue&#xa0;: %1)</translation>
    </message>
    <message>
        <source>the mask&apos;s offset %1 is absurd</source>
        <translation>le décalage %1 du masque est absurde</translation>
    </message>
    <message>
        <source>mask coefficient %1 is not a finite number</source>
        <translation>le coefficient %1 du masque n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <source>the coefficients a_k with k = %1 mod %2 sum to %3, not 1: every coset of the mask must sum to 1 (the scheme must reproduce constants; the whole mask sums to the arity %2)</source>
        <translation>les coefficients a_k avec k = %1 mod %2 ont pour somme %3, et non 1&#xa0;: chaque classe résiduelle du masque doit avoir pour somme 1 (le schéma doit reproduire les constantes&#xa0;; la somme du masque entier vaut l&apos;arité %2)</translation>
    </message>
    <message>
        <source>mask of arity %1</source>
        <translation>masque d&apos;arité %1</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Subdivision curves as attractors of IFS.</source>
        <translation>Les courbes de subdivision comme attracteurs d’IFS.</translation>
    </message>
    <message>
        <source>Project file to open.</source>
        <translation>Fichier de projet à ouvrir.</translation>
    </message>
    <message>
        <source>Select the item with this name after opening.</source>
        <translation>Sélectionner l’élément portant ce nom après l’ouverture.</translation>
    </message>
    <message>
        <source>Print the current item&apos;s figure sheet to this PDF file, then quit.</source>
        <translation>Imprimer la fiche de figure de l’élément courant dans ce fichier PDF, puis quitter.</translation>
    </message>
    <message>
        <source>Save a picture of the main window to this PNG file once the attractor is drawn, then quit.</source>
        <translation>Enregistrer une image de la fenêtre principale dans ce fichier PNG une fois l’attracteur tracé, puis quitter.</translation>
    </message>
    <message>
        <source>Window size for --screenshot, WIDTHxHEIGHT.</source>
        <translation>Taille de la fenêtre pour --screenshot, LARGEURxHAUTEUR.</translation>
    </message>
    <message>
        <source>Export a figure of the current item to this file (.png, .svg, .pdf; .tex for the matrices), then quit.</source>
        <translation>Exporter une figure de l’élément courant dans ce fichier (.png, .svg, .pdf&#x202f;; .tex pour les matrices), puis quitter.</translation>
    </message>
    <message>
        <source>Resolution of --export-figure in dpi (36..2400).</source>
        <translation>Résolution de --export-figure en ppp (36..2400).</translation>
    </message>
    <message>
        <source>What --export-figure shows: attractor, spectrum, matrices, analysis or sheet.</source>
        <translation>Contenu de --export-figure&#xa0;: attractor, spectrum, matrices, analysis ou sheet.</translation>
    </message>
    <message>
        <source>Size of --export-figure in pixels at its resolution, WIDTHxHEIGHT (16..20000).</source>
        <translation>Taille de --export-figure en pixels à sa résolution, LARGEURxHAUTEUR (16..20000).</translation>
    </message>
    <message>
        <source>--export-figure without the grid.</source>
        <translation>--export-figure sans la grille.</translation>
    </message>
    <message>
        <source>--export-figure without control polygons and start set.</source>
        <translation>--export-figure sans les polygones de contrôle ni l’ensemble initial.</translation>
    </message>
    <message>
        <source>--export-figure framed tightly around the content (the height follows its proportions).</source>
        <translation>--export-figure cadré au plus près du contenu (la hauteur suit ses proportions).</translation>
    </message>
    <message>
        <source>Font of --export-figure&apos;s labels: FAMILY or FAMILY,POINTS.</source>
        <translation>Police des étiquettes de --export-figure&#xa0;: FAMILLE ou FAMILLE,POINTS.</translation>
    </message>
</context>
</TS>
