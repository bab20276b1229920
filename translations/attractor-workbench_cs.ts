<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ" sourcelanguage="en">
<context>
    <name></name>
    <message>
        <source>valence %1, %2, %3</source>
        <translation type="vanished">valence %1, %2, %3</translation>
    </message>
    <message>
        <source>on the boundary</source>
        <translation type="vanished">na hranici</translation>
    </message>
    <message>
        <source>interior</source>
        <translation type="vanished">vnitřní</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the net of the vertex&apos;s piece).</source>
        <translation type="vanished">Lokální matice subdivize S: %1 × %1 (síť části, k níž vrchol patří).</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the vertex and every point within two faces of it).</source>
        <translation type="vanished">Lokální matice subdivize S: %1 × %1 (vrchol a všechny body vzdálené od něj nejvýše dvě stěny).</translation>
    </message>
    <message>
        <source>λ₁ = 1, λ = %1, μ = %2, λ² = %3</source>
        <translation type="vanished">λ₁ = 1, λ = %1, μ = %2, λ² = %3</translation>
    </message>
    <message>
        <source> (λ in closed form: %1)</source>
        <translation type="vanished"> (λ v uzavřeném tvaru: %1)</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for interior vertices only: a boundary vertex follows the crease rules, whose analysis needs the boundary&apos;s own characteristic map.</source>
        <translation type="vanished">Reifovo kritérium se zde rozhoduje jen pro vnitřní vrcholy: hraniční vrchol se řídí pravidly pro ostré hrany, jejichž analýza vyžaduje vlastní charakteristické zobrazení hranice.</translation>
    </message>
    <message>
        <source>spectral condition 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ real</source>
        <translation type="vanished">spektrální podmínka 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ reálné</translation>
    </message>
    <message>
        <source>characteristic map regular: the Jacobian keeps one sign on all %1 cells (signed areas %2 … %3)</source>
        <translation type="vanished">charakteristické zobrazení je regulární: jakobián má na všech %1 buňkách stejné znaménko (orientované obsahy %2 … %3)</translation>
    </message>
    <message>
        <source>characteristic map not regular: signed areas from %1 to %2</source>
        <translation type="vanished">charakteristické zobrazení není regulární: orientované obsahy od %1 do %2</translation>
    </message>
    <message>
        <source>characteristic map injective: its boundary winds %1 time(s) around the vertex</source>
        <translation type="vanished">injektivita charakteristického zobrazení: jeho hranice oběhne vrchol %1krát</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): the limit surface is C¹ at the vertex (for generic data).</source>
        <translation type="vanished">Verdikt (Reif 1995): limitní plocha je ve vrcholu C¹ (pro generická data).</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): C¹ is not established at the vertex.</source>
        <translation type="vanished">Verdikt (Reif 1995): C¹ ve vrcholu není prokázáno.</translation>
    </message>
    <message>
        <source>μ &lt; λ²: the curvature is zero at the vertex (the surface is flat there to second order, for generic data: no convex or saddle shape can be modelled at it)</source>
        <translation type="vanished">μ &lt; λ²: křivost ve vrcholu je nulová (pro generická data je tam plocha do druhého řádu rovinná: nelze v něm modelovat konvexní ani sedlový tvar)</translation>
    </message>
    <message>
        <source>μ = λ²: the curvature is bounded at the vertex</source>
        <translation type="vanished">μ = λ²: křivost ve vrcholu je omezená</translation>
    </message>
    <message>
        <source>μ &gt; λ²: the curvature is unbounded at the vertex (for generic data)</source>
        <translation type="vanished">μ &gt; λ²: křivost ve vrcholu je neomezená (pro generická data)</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3), normal (%4, %5, %6).</source>
        <translation type="vanished">Limitní poloha (%1, %2, %3), normála (%4, %5, %6).</translation>
    </message>
</context>
<context>
    <name>ExportDialog</name>
    <message>
        <source>Export Figure</source>
        <translation>Exportovat obrázek</translation>
    </message>
    <message>
        <source>&amp;View:</source>
        <translation>Pohle&amp;d:</translation>
    </message>
    <message>
        <source>The view or figure to export.</source>
        <translation>Pohled nebo obrázek, který se má exportovat.</translation>
    </message>
    <message>
        <source>Attractor view</source>
        <translation>Pohled atraktoru</translation>
    </message>
    <message>
        <source>Spectrum plot</source>
        <translation>Graf spektra</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>Matice</translation>
    </message>
    <message>
        <source>Analysis chart (current tab)</source>
        <translation>Graf analýzy (aktuální karta)</translation>
    </message>
    <message>
        <source>Figure sheet</source>
        <translation>List s obrázkem</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Soubor:</translation>
    </message>
    <message>
        <source>File to write; its suffix (.png, .svg or .pdf; .tex for the matrices as LaTeX) picks the format.</source>
        <translation>Soubor k zápisu; jeho přípona (.png, .svg nebo .pdf; .tex pro matice v LaTeXu) určuje formát.</translation>
    </message>
    <message>
        <source>Choose the file to write.</source>
        <translation>Vyberte soubor k zápisu.</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Procházet…</translation>
    </message>
    <message>
        <source>The suffix picks the format: .png, .svg or .pdf (the Matrices view also .tex: LaTeX bmatrix).</source>
        <translation>Formát určuje přípona: .png, .svg nebo .pdf (u pohledu Matice také .tex: LaTeX bmatrix).</translation>
    </message>
    <message>
        <source>&amp;Width:</source>
        <translation>Šíř&amp;ka:</translation>
    </message>
    <message>
        <source>Width of the figure in pixels (for SVG and PDF: pixel units at the resolution below).</source>
        <translation>Šířka obrázku v pixelech (u SVG a PDF: pixelové jednotky při níže uvedeném rozlišení).</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>&amp;Height:</source>
        <translation>&amp;Výška:</translation>
    </message>
    <message>
        <source>Height of the figure in pixels (for SVG and PDF: pixel units at the resolution below).</source>
        <translation>Výška obrázku v pixelech (u SVG a PDF: pixelové jednotky při níže uvedeném rozlišení).</translation>
    </message>
    <message>
        <source>&amp;Resolution:</source>
        <translation>&amp;Rozlišení:</translation>
    </message>
    <message>
        <source>Resolution in dots per inch (dpi).</source>
        <translation>Rozlišení v bodech na palec (dpi).</translation>
    </message>
    <message>
        <source> dpi</source>
        <translation> dpi</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>Zobrazit:</translation>
    </message>
    <message>
        <source>Draw the coordinate grid and its labels (when the view shows them).</source>
        <translation>Vykreslit souřadnicovou mřížku a její popisky (pokud je pohled zobrazuje).</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>&amp;Mřížka</translation>
    </message>
    <message>
        <source>Draw the control polygons, the start set and their points and labels.</source>
        <translation>Vykreslit řídicí polygony, počáteční množinu a jejich body a popisky.</translation>
    </message>
    <message>
        <source>&amp;Control points</source>
        <translation>Řídi&amp;cí body</translation>
    </message>
    <message>
        <source>Frame the attractor view&apos;s content tightly: the height follows the content&apos;s proportions (the width is kept).</source>
        <translation>Těsně ohraničit obsah pohledu atraktoru: výška se řídí proporcemi obsahu (šířka zůstane zachována).</translation>
    </message>
    <message>
        <source>C&amp;rop to contents</source>
        <translation>Oříz&amp;nout na obsah</translation>
    </message>
    <message>
        <source>F&amp;ont:</source>
        <translation>Písm&amp;o:</translation>
    </message>
    <message>
        <source>Font of the labels and of the figure sheet&apos;s text.</source>
        <translation>Písmo popisků a textu listu s obrázkem.</translation>
    </message>
    <message>
        <source>Label size in points as the figure is shown at its resolution (0: as on screen).</source>
        <translation>Velikost popisků v bodech při zobrazení obrázku v jeho rozlišení (0: jako na obrazovce).</translation>
    </message>
    <message>
        <source>as on screen</source>
        <translation>jako na obrazovce</translation>
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
        <translation>Předvolby</translation>
    </message>
    <message>
        <source>Default &amp;depth of new items:</source>
        <translation>Výchozí &amp;hloubka nových položek:</translation>
    </message>
    <message>
        <source>Deterministic depth given to new items.</source>
        <translation>Deterministická hloubka, kterou dostanou nové položky.</translation>
    </message>
    <message>
        <source>&amp;Maximum drawn depth:</source>
        <translation>&amp;Maximální vykreslovaná hloubka:</translation>
    </message>
    <message>
        <source>Draw at most this depth, whatever the item asks for.</source>
        <translation>Vykreslovat nejvýše do této hloubky bez ohledu na to, co požaduje položka.</translation>
    </message>
    <message>
        <source>no limit</source>
        <translation>bez omezení</translation>
    </message>
    <message>
        <source>Map &amp;colours:</source>
        <translation>&amp;Barvy zobrazení:</translation>
    </message>
    <message>
        <source>Colour of map 1</source>
        <translation>Barva zobrazení 1</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>automaticky</translation>
    </message>
    <message>
        <source>Colour of map 2</source>
        <translation>Barva zobrazení 2</translation>
    </message>
    <message>
        <source>Colour of map 3</source>
        <translation>Barva zobrazení 3</translation>
    </message>
    <message>
        <source>Colour of map 4</source>
        <translation>Barva zobrazení 4</translation>
    </message>
    <message>
        <source>Colour of map 5</source>
        <translation>Barva zobrazení 5</translation>
    </message>
    <message>
        <source>Colour of map 6</source>
        <translation>Barva zobrazení 6</translation>
    </message>
    <message>
        <source>Use the views&apos; default colours for all maps.</source>
        <translation>Použít pro všechna zobrazení výchozí barvy pohledů.</translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation>Výchozí</translation>
    </message>
    <message>
        <source>&amp;Autosave interval:</source>
        <translation>Interval &amp;automatického ukládání:</translation>
    </message>
    <message>
        <source>Time between automatic saves of a recovery copy of the project, in seconds.</source>
        <translation>Doba mezi automatickými uloženími záložní kopie projektu, v sekundách.</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Dask &amp;scheduler:</source>
        <translation>&amp;Plánovač Dask:</translation>
    </message>
    <message>
        <source>The address of a running Dask scheduler (tcp://host:8786) on which the Regularity Atlas computes; empty: a local cluster of this machine&apos;s cores.</source>
        <translation>Adresa běžícího plánovače Dask (tcp://host:8786), na kterém Atlas regularity počítá; prázdné: místní cluster z jader tohoto počítače.</translation>
    </message>
    <message>
        <source>a local cluster of this machine</source>
        <translation>místní cluster tohoto počítače</translation>
    </message>
    <message>
        <source>&amp;Local workers:</source>
        <translation>&amp;Místní pracovní procesy:</translation>
    </message>
    <message>
        <source>Worker processes of the local Dask cluster (the Regularity Atlas without a scheduler address).</source>
        <translation>Pracovní procesy místního clusteru Dask (Atlas regularity bez adresy plánovače).</translation>
    </message>
    <message>
        <source>one per core</source>
        <translation>jeden na jádro</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>%1, Hölder regularity r in [%2, %3] (width %4)</source>
        <translation>%1, Hölderovská regularita r v [%2, %3] (šířka %4)</translation>
    </message>
    <message>
        <source>%1, Hölder regularity r = %2 (exact)</source>
        <translation>%1, Hölderovská regularita r = %2 (přesně)</translation>
    </message>
    <message>
        <source>%1, Hölder regularity r = %2 (exact: invariant polytope, certificate)</source>
        <translation>%1, Hölderovská regularita r = %2 (přesně: invariantní polytop, certifikát)</translation>
    </message>
    <message>
        <source>; Sobolev (L²) exponent s₂ = %1</source>
        <translation>; Sobolevův (L²) exponent s₂ = %1</translation>
    </message>
</context>
<context>
    <name>awb</name>
    <message>
        <source>the SVG does not parse: %1 (line %2, column %3)</source>
        <translation>SVG nelze přečíst: %1 (řádek %2, sloupec %3)</translation>
    </message>
    <message>
        <source>%1: cannot read the figure: %2</source>
        <translation>%1: obrázek nelze přečíst: %2</translation>
    </message>
    <message>
        <source>larger than 512 MB</source>
        <translation>větší než 512 MB</translation>
    </message>
    <message>
        <source>neither a PNG nor an SVG</source>
        <translation>není PNG ani SVG</translation>
    </message>
    <message>
        <source>its project is larger than 64 MB</source>
        <translation>jeho projekt je větší než 64 MB</translation>
    </message>
    <message>
        <source>%1: this %2 holds no Attractor Workbench item (only figures exported by Attractor Workbench carry their parameters)</source>
        <translation>%1: tento %2 neobsahuje žádnou položku Attractor Workbench (parametry nesou jen obrázky exportované z Attractor Workbench)</translation>
    </message>
</context>
<context>
    <name>awb::AddressPanel</name>
    <message>
        <source>Address 0,1,1 or interval [0.25, 0.5]</source>
        <translation>Adresa 0,1,1 nebo interval [0.25, 0.5]</translation>
    </message>
    <message>
        <source>An address selects the sub-copy f_w(A) = f_w1(f_w2(…(A))): map numbers from 0, the outermost map first. A subdivision curve also takes a parameter interval [t0, t1]. Enter selects, an empty field clears.</source>
        <translation>Adresa vybírá dílčí kopii f_w(A) = f_w1(f_w2(…(A))): zobrazení se číslují od 0, jako první se uvádí vnější zobrazení. Subdivizní křivka přijímá také interval parametru [t0, t1]. Enter výběr provede, prázdné pole výběr zruší.</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Vymazat</translation>
    </message>
    <message>
        <source>Click the attractor to pick an address; click a symbol of it to select that prefix.</source>
        <translation>Kliknutím na atraktor vyberete adresu; kliknutím na některý její symbol vyberete příslušný prefix.</translation>
    </message>
    <message>
        <source>address %1</source>
        <translation>adresa %1</translation>
    </message>
    <message>
        <source>, t ≈ %1</source>
        <translation>, t ≈ %1</translation>
    </message>
    <message>
        <source>Clicked: %1&lt;br&gt;&lt;small&gt;click a symbol to select the prefix up to it&lt;/small&gt;</source>
        <translation>Kliknuto: %1&lt;br&gt;&lt;small&gt;kliknutím na symbol vyberete prefix až po něj&lt;/small&gt;</translation>
    </message>
    <message>
        <source>The item drawn has no addresses to select (only items drawn by one IFS in the plane have).</source>
        <translation>Vykreslená položka nemá žádné adresy k výběru (mají je jen položky kreslené jedním IFS v rovině).</translation>
    </message>
    <message>
        <source>a parameter interval selects on a subdivision curve with a real parameter; this item has none</source>
        <translation>interval parametru vybírá úsek subdivizní křivky s reálným parametrem; tato položka takový parametr nemá</translation>
    </message>
    <message>
        <source>t in %1</source>
        <translation>t v %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;t in %1&lt;/b&gt; (%2)&lt;br&gt;Pieces inside it (addresses up to 8 symbols): %3</source>
        <translation>&lt;b&gt;t v %1&lt;/b&gt; (%2)&lt;br&gt;Části uvnitř (adresy do 8 symbolů): %3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádné</translation>
    </message>
    <message>
        <source>&lt;br&gt;The control polygons of the first %1 pieces are drawn.</source>
        <translation>&lt;br&gt;Jsou vykresleny řídicí polygony prvních %1 částí.</translation>
    </message>
    <message>
        <source>w = %1</source>
        <translation>w = %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;w = %1&lt;/b&gt;: the sub-copy f_w(A) = %2(A)</source>
        <translation>&lt;b&gt;w = %1&lt;/b&gt;: dílčí kopie f_w(A) = %2(A)</translation>
    </message>
    <message>
        <source>   t in [%1, %2]</source>
        <translation>   t v [%1, %2]</translation>
    </message>
    <message>
        <source>&lt;br&gt;t in [%1, %2] (%3)</source>
        <translation>&lt;br&gt;t v [%1, %2] (%3)</translation>
    </message>
    <message>
        <source>&lt;br&gt;Control points S_w P = %1 (symbol i is S_(i+1)):&lt;br&gt;%2</source>
        <translation>&lt;br&gt;Řídicí body S_w P = %1 (symbolu i odpovídá S_(i+1)):&lt;br&gt;%2</translation>
    </message>
</context>
<context>
    <name>awb::AlgorithmSpec</name>
    <message>
        <source>the depth cannot be negative, got %1</source>
        <translation>hloubka nemůže být záporná, zadáno %1</translation>
    </message>
    <message>
        <source>depth %1 is absurd: at most %2 is allowed</source>
        <translation>hloubka %1 je nesmyslná: povoleno je nejvýše %2</translation>
    </message>
    <message>
        <source>the sample count must be between 1 and 2^31, got %1</source>
        <translation>počet vzorků musí být mezi 1 a 2^31, zadáno %1</translation>
    </message>
    <message>
        <source>the seed must be between 0 and 2^53 - 1, got %1</source>
        <translation>semínko generátoru musí být mezi 0 a 2^53 - 1, zadáno %1</translation>
    </message>
    <message>
        <source>probability %1 must be a finite number &gt;= 0</source>
        <translation>pravděpodobnost %1 musí být konečné číslo &gt;= 0</translation>
    </message>
    <message>
        <source>the probabilities sum to 0</source>
        <translation>součet pravděpodobností je 0</translation>
    </message>
    <message>
        <source>depth %1 with %2 maps makes %3 images of the start set, more than 2^31: at most depth %4 for %2 maps</source>
        <translation>hloubka %1 se %2 zobrazeními dává %3 obrazů počáteční množiny, víc než 2^31: nejvýše hloubka %4 pro %2 zobrazení</translation>
    </message>
</context>
<context>
    <name>awb::AnalysisCharts</name>
    <message>
        <source>Distance to the exact curve</source>
        <translation>Vzdálenost od přesné křivky</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>Vzdálenost</translation>
    </message>
    <message>
        <source>Control polygon length</source>
        <translation>Délka řídicího polygonu</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Délka</translation>
    </message>
    <message>
        <source>Box counting</source>
        <translation>Počítání krabic</translation>
    </message>
    <message>
        <source>Eigenvalue moduli</source>
        <translation>Moduly vlastních čísel</translation>
    </message>
    <message>
        <source>|λ| per map</source>
        <translation>|λ| pro jednotlivá zobrazení</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;depth k = %2&lt;br&gt;d&lt;sub&gt;H&lt;/sub&gt; = %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;hloubka k = %2&lt;br&gt;d&lt;sub&gt;H&lt;/sub&gt; = %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;step k = %2&lt;br&gt;length = %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;krok k = %2&lt;br&gt;délka = %3</translation>
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
        <translation>hloubka k</translation>
    </message>
    <message>
        <source>Hausdorff distance</source>
        <translation>Hausdorffova vzdálenost</translation>
    </message>
    <message>
        <source>control polygon</source>
        <translation>řídicí polygon</translation>
    </message>
    <message>
        <source>exact curve</source>
        <translation>přesná křivka</translation>
    </message>
    <message>
        <source>subdivision step k</source>
        <translation>krok subdivize k</translation>
    </message>
    <message>
        <source>length</source>
        <translation>délka</translation>
    </message>
    <message>
        <source>Box counting: no fit (%1)</source>
        <translation>Počítání krabic: bez proložení (%1)</translation>
    </message>
    <message>
        <source>not fitted</source>
        <translation>neproloženo</translation>
    </message>
    <message>
        <source>fitted levels</source>
        <translation>proložené úrovně</translation>
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
        <translation>zobrazení</translation>
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
        <translation>Pro tuto položku není známa přesná křivka</translation>
    </message>
    <message>
        <source>The Hausdorff distance is measured against an exact curve: B-spline, Bézier and complex de Casteljau curves have one.</source>
        <translation>Hausdorffova vzdálenost se měří vůči přesné křivce: mají ji B-spline křivky, Bézierovy křivky a komplexní de Casteljauovy křivky.</translation>
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
        <translation>Krabicová dimenze D = %1: sklon log N(ε) vůči log(1/ε) na proložených úrovních, log N = %1 log(1/ε) + %2, R² = %3</translation>
    </message>
    <message>
        <source>No fit</source>
        <translation>Bez proložení</translation>
    </message>
    <message>
        <source>slope %1</source>
        <translation>sklon %1</translation>
    </message>
</context>
<context>
    <name>awb::Animation</name>
    <message>
        <source>expected a duration in seconds above 0 and at most %1</source>
        <translation>očekávána délka v sekundách větší než 0 a nejvýše %1</translation>
    </message>
    <message>
        <source>expected between 1 and %1 frames per second</source>
        <translation>očekáváno 1 až %1 snímků za sekundu</translation>
    </message>
    <message>
        <source>%1 s at %2 frames per second makes more than %3 frames</source>
        <translation>%1 s při %2 snímcích za sekundu dává více než %3 snímků</translation>
    </message>
    <message>
        <source>names no parameter</source>
        <translation>neurčuje žádný parametr</translation>
    </message>
    <message>
        <source>%1 is driven by an earlier track already</source>
        <translation>%1 už je řízen dřívější stopou</translation>
    </message>
    <message>
        <source>needs at least one key</source>
        <translation>vyžaduje alespoň jeden klíč</translation>
    </message>
    <message>
        <source>expected a time between 0 and the duration, %1 s</source>
        <translation>očekáván čas mezi 0 a délkou animace, %1 s</translation>
    </message>
    <message>
        <source>key times must increase (%1 s follows %2 s)</source>
        <translation>časy klíčů musí narůstat (%1 s následuje po %2 s)</translation>
    </message>
    <message>
        <source>expected %1 numbers, as the first key</source>
        <translation>očekávaný počet čísel je %1, stejně jako u prvního klíče</translation>
    </message>
    <message>
        <source>not a finite number</source>
        <translation>není konečné číslo</translation>
    </message>
    <message>
        <source>a circle turns a point or a complex value, not one number</source>
        <translation>kružnice otáčí bodem nebo komplexní hodnotou, ne jedním číslem</translation>
    </message>
    <message>
        <source>expected [x, y]</source>
        <translation>očekáváno [x, y]</translation>
    </message>
    <message>
        <source>expected a number of turns between -1000 and 1000</source>
        <translation>očekáván počet otáček mezi -1000 a 1000</translation>
    </message>
    <message>
        <source>Probabilities</source>
        <translation>Pravděpodobnosti</translation>
    </message>
    <message>
        <source>Points %1, point %2</source>
        <translation>Sada bodů %1, bod %2</translation>
    </message>
    <message>
        <source>Control point %1</source>
        <translation>Řídicí bod %1</translation>
    </message>
    <message>
        <source>%1 has no probabilities</source>
        <translation>%1 nemá pravděpodobnosti</translation>
    </message>
    <message>
        <source>%1 has no control point %2 in point set %3</source>
        <translation>%1 nemá řídicí bod %2 v sadě bodů %3</translation>
    </message>
    <message>
        <source>%1 is not a number that can be animated</source>
        <translation>%1 není číslo, které lze animovat</translation>
    </message>
    <message>
        <source>%1 has no parameter %2 (now)</source>
        <translation>%1 (nyní) nemá parametr %2</translation>
    </message>
    <message>
        <source>no such control point</source>
        <translation>takový řídicí bod neexistuje</translation>
    </message>
    <message>
        <source>the point was refused</source>
        <translation>bod byl odmítnut</translation>
    </message>
    <message>
        <source>no such parameter now</source>
        <translation>takový parametr nyní neexistuje</translation>
    </message>
    <message>
        <source>a complex value needs 2 numbers</source>
        <translation>komplexní hodnota vyžaduje 2 čísla</translation>
    </message>
    <message>
        <source>%1 at %2 s: %3</source>
        <translation>%1 v čase %2 s: %3</translation>
    </message>
    <message>
        <source>the value was refused</source>
        <translation>hodnota byla odmítnuta</translation>
    </message>
    <message>
        <source>%1 has %2 coordinates, the keys %3</source>
        <translation>%1 má souřadnic: %2, klíče: %3</translation>
    </message>
    <message>
        <source>p = (%1)</source>
        <translation>p = (%1)</translation>
    </message>
    <message>
        <source>t = %1 s: %2</source>
        <translation>t = %1 s: %2</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>chybí</translation>
    </message>
    <message>
        <source>expected an array of tracks</source>
        <translation>očekáváno pole stop</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>očekáván objekt</translation>
    </message>
    <message>
        <source>expected an array of keys</source>
        <translation>očekáváno pole klíčů</translation>
    </message>
    <message>
        <source>expected an object {&quot;time&quot;, &quot;value&quot;}</source>
        <translation>očekáván objekt {&quot;time&quot;, &quot;value&quot;}</translation>
    </message>
    <message>
        <source>unknown field of a key</source>
        <translation>neznámé pole klíče</translation>
    </message>
    <message>
        <source>unknown field of a track</source>
        <translation>neznámé pole stopy</translation>
    </message>
    <message>
        <source>unknown field of an animation</source>
        <translation>neznámé pole animace</translation>
    </message>
</context>
<context>
    <name>awb::AnimationPanel</name>
    <message>
        <source>Play / pause the animation (Ctrl+Space)</source>
        <translation>Přehrát / pozastavit animaci (Ctrl+Space)</translation>
    </message>
    <message>
        <source>Stop: the views show the item itself again</source>
        <translation>Zastavit: pohledy opět zobrazí samotnou položku</translation>
    </message>
    <message>
        <source>Time: drag to see the frames (the views follow)</source>
        <translation>Čas: tažením procházíte snímky (pohledy je sledují)</translation>
    </message>
    <message>
        <source>Time and frame number</source>
        <translation>Čas a číslo snímku</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Opakovat</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Přehrát</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Zastavit</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Duration of the animation</source>
        <translation>Délka animace</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>Snímky za sekundu</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>Parameter / key time (s)</source>
        <translation>Parametr / čas klíče (s)</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Hodnota</translation>
    </message>
    <message>
        <source>Double-click a key&apos;s time or value to edit it</source>
        <translation>Čas nebo hodnotu klíče upravíte dvojitým kliknutím</translation>
    </message>
    <message>
        <source>The parameter, probabilities or control point to key</source>
        <translation>Parametr, pravděpodobnosti nebo řídicí bod, pro který se nastaví klíč</translation>
    </message>
    <message>
        <source>Set Key</source>
        <translation>Nastavit klíč</translation>
    </message>
    <message>
        <source>Store the item&apos;s present value of the parameter at the time shown (replaces a key at that time)</source>
        <translation>Uloží současnou hodnotu parametru položky v zobrazeném čase (nahradí klíč v tomto čase)</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Odebrat</translation>
    </message>
    <message>
        <source>Remove the selected key, or the selected track with its keys</source>
        <translation>Odstraní vybraný klíč nebo vybranou stopu i s jejími klíči</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineární</translation>
    </message>
    <message>
        <source>Smooth (ease in and out)</source>
        <translation>Hladká (plynulý náběh a doběh)</translation>
    </message>
    <message>
        <source>Through the keys</source>
        <translation>Přes klíče</translation>
    </message>
    <message>
        <source>Circle about a centre</source>
        <translation>Kružnice kolem středu</translation>
    </message>
    <message>
        <source>x, y</source>
        <translation>x, y</translation>
    </message>
    <message>
        <source>Interpolation</source>
        <translation>Interpolace</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Dráha</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>Střed</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>Otáčky</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastavit</translation>
    </message>
    <message>
        <source>The views show the item itself.</source>
        <translation>Pohledy zobrazují samotnou položku.</translation>
    </message>
    <message>
        <source>%1 s · %2/%3</source>
        <translation>%1 s · %2/%3</translation>
    </message>
    <message>
        <source>Frame at %1 s: %2</source>
        <translation>Snímek v čase %1 s: %2</translation>
    </message>
    <message>
        <source>The views show the frame at %1 s (not editable); Stop returns to the item.</source>
        <translation>Pohledy zobrazují snímek v čase %1 s (nelze upravovat); tlačítko Zastavit vrátí zobrazení položky.</translation>
    </message>
    <message>
        <source>No item is selected.</source>
        <translation>Není vybrána žádná položka.</translation>
    </message>
    <message>
        <source>Select a key or a track to remove.</source>
        <translation>Vyberte klíč nebo stopu, které chcete odstranit.</translation>
    </message>
    <message>
        <source>inactive: %1 has no such input now</source>
        <translation>neaktivní: %1 nyní takový vstup nemá</translation>
    </message>
    <message>
        <source>circle about (%1), %2 turns</source>
        <translation>kružnice kolem (%1), otáček: %2</translation>
    </message>
    <message>
        <source>The item does not have %1 in its present state (another scheme, fewer points): the track is kept and skipped.</source>
        <translation>Položka ve svém současném stavu nemá %1 (jiné schéma, méně bodů): stopa se zachová, ale přeskočí se.</translation>
    </message>
    <message>
        <source>Select an item to animate its parameters.</source>
        <translation>Vyberte položku, jejíž parametry chcete animovat.</translation>
    </message>
    <message>
        <source>No keys yet: set a value in Properties, choose it here and press Set Key; then move the slider, change the value and key it again.</source>
        <translation>Zatím žádné klíče: nastavte hodnotu ve Vlastnostech, vyberte ji zde a stiskněte Nastavit klíč; pak posuňte posuvník, změňte hodnotu a nastavte další klíč.</translation>
    </message>
    <message>
        <source>%1 has no numeric parameters to animate.</source>
        <translation>%1 nemá žádné číselné parametry k animaci.</translation>
    </message>
    <message>
        <source>%1 tracks, %2 frames. Play or drag the slider to preview.</source>
        <translation>Stopy: %1, snímky: %2. Náhled zobrazíte přehráním nebo tažením posuvníku.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a time in seconds</source>
        <translation>„%1“ není čas v sekundách</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: expected %2 numbers</source>
        <translation>„%1“: očekávaný počet čísel je %2</translation>
    </message>
</context>
<context>
    <name>awb::AtlasPlot</name>
    <message>
        <source>upper bound on r</source>
        <translation>horní mez r</translation>
    </message>
    <message>
        <source>lower bound on r (certified)</source>
        <translation>dolní mez r (certifikovaná)</translation>
    </message>
    <message>
        <source>Hölder exponent r</source>
        <translation>Hölderův exponent r</translation>
    </message>
    <message>
        <source>Shaded: certified C&lt;sup&gt;%1&lt;/sup&gt; (lower bound &amp;gt; %1). %2 points.</source>
        <translation>Vystínováno: certifikovaně C&lt;sup&gt;%1&lt;/sup&gt; (dolní mez &amp;gt; %1). Bodů: %2.</translation>
    </message>
    <message>
        <source>not certified C⁰</source>
        <translation>necertifikováno C⁰</translation>
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
        <translation>C³ nebo více</translation>
    </message>
    <message>
        <source>&lt;span style=&quot;color:#c83c14&quot;&gt;□&lt;/span&gt; the bounds cannot tell C&lt;sup&gt;%1&lt;/sup&gt;; white: no member. %2 points.</source>
        <translation>&lt;span style=&quot;color:#c83c14&quot;&gt;□&lt;/span&gt; meze nerozhodnou o C&lt;sup&gt;%1&lt;/sup&gt;; bílá: žádný člen. Bodů: %2.</translation>
    </message>
    <message>
        <source>no member here: %1</source>
        <translation>zde žádný člen: %1</translation>
    </message>
    <message>
        <source>C^∞ (a polynomial piece)</source>
        <translation>C^∞ (polynomiální úsek)</translation>
    </message>
    <message>
        <source>Hölder exponent r in [%1, %2]%3</source>
        <translation>Hölderův exponent r v [%1, %2]%3</translation>
    </message>
    <message>
        <source>, exact (invariant polytope)</source>
        <translation>, přesně (invariantní polytop)</translation>
    </message>
    <message>
        <source>certified C^%1</source>
        <translation>certifikovaně C^%1</translation>
    </message>
    <message>
        <source>C^%1 as asked: yes</source>
        <translation>Požadované C^%1: ano</translation>
    </message>
    <message>
        <source>C^%1 as asked: certified no</source>
        <translation>Požadované C^%1: certifikovaně ne</translation>
    </message>
    <message>
        <source>C^%1 as asked: the bounds cannot tell</source>
        <translation>Požadované C^%1: meze nerozhodnou</translation>
    </message>
    <message>
        <source>Sobolev exponent s₂ = %1</source>
        <translation>Sobolevův exponent s₂ = %1</translation>
    </message>
    <message>
        <source>stopped by the safety clock: may differ on another machine</source>
        <translation>zastaveno bezpečnostním časovým limitem: na jiném počítači se může lišit</translation>
    </message>
    <message>
        <source>Click to add an item with these parameters.</source>
        <translation>Kliknutím přidáte položku s těmito parametry.</translation>
    </message>
</context>
<context>
    <name>awb::AttractorItem</name>
    <message>
        <source>Change start set of %1</source>
        <translation>Změnit počáteční množinu položky %1</translation>
    </message>
    <message>
        <source>Change algorithm of %1</source>
        <translation>Změnit algoritmus položky %1</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n control points of %1</source>
        <translation>
            <numerusform>Odstranit %n řídicí bod položky %1</numerusform>
            <numerusform>Odstranit %n řídicí body položky %1</numerusform>
            <numerusform>Odstranit %n řídicích bodů položky %1</numerusform>
        </translation>
    </message>
    <message>
        <source>map %1 is not finite: the control points&apos; coordinates overflow in the lifted map P⁻¹ S_i P (the largest is %2)</source>
        <translation>zobrazení %1 není konečné: souřadnice řídicích bodů přetékají ve zdviženém zobrazení P⁻¹ S_i P (největší je %2)</translation>
    </message>
    <message>
        <source>the start set is not finite in the IFS space: the lifting overflows (the largest control point coordinate is %1)</source>
        <translation>počáteční množina není v prostoru IFS konečná: zdvižení přetéká (největší souřadnice řídicího bodu je %1)</translation>
    </message>
    <message>
        <source>lifted start points need an invertible lifting: %1</source>
        <translation>zdvižené počáteční body vyžadují invertibilní zdvižení: %1</translation>
    </message>
    <message>
        <source>a lifted start point of this item has %1 coordinates (x, y and the %2 extra coordinates of the lifting, the homogeneous 1 implied); point %3 has %4</source>
        <translation>zdvižený počáteční bod této položky má mít počet souřadnic %1 (x, y a dodatečné souřadnice zdvižení v počtu %2, homogenní 1 se doplní); bod %3 jich má %4</translation>
    </message>
    <message>
        <source>%1 points; an item takes at most %2 (its subdivision matrices would be %1 x %1)</source>
        <translation>počet bodů %1; položka jich připouští nejvýše %2 (její subdivizní matice by měly rozměr %1 x %1)</translation>
    </message>
    <message>
        <source>point set %1 has %2 points; an item takes at most %3 per set</source>
        <translation>sada bodů %1 má %2 bodů; položka připouští nejvýše %3 bodů v jedné sadě</translation>
    </message>
    <message>
        <source>the start set &quot;vertex-limits&quot; (the limit positions of a mesh&apos;s vertices) is for mesh items only; this item: %1</source>
        <translation>počáteční množina &quot;vertex-limits&quot; (limitní polohy vrcholů sítě) je jen pro položky se sítí; tato položka: %1</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Bod</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Úsečka</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation>Trojúhelníkový</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Mnohoúhelník</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Body</translation>
    </message>
    <message>
        <source>Lifted points</source>
        <translation>Zdvižené body</translation>
    </message>
    <message>
        <source>Vertex limits</source>
        <translation>Limitní polohy vrcholů</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Druh</translation>
    </message>
    <message>
        <source>Start set X0</source>
        <translation>Počáteční množina X0</translation>
    </message>
    <message>
        <source>The set X0 deterministic iteration starts from; drag its vertices in the attractor view. Lifted points are points of the lifted space of 000 §2; vertex limits, a mesh&apos;s vertices&apos; limit positions.</source>
        <translation type="vanished">Množina X0, z níž vychází deterministická iterace; její vrcholy přetáhněte v pohledu atraktoru. Zdvižené body jsou body zdviženého prostoru podle 000 §2; limitní polohy vrcholů jsou polohy, k nimž v limitě směřují vrcholy sítě.</translation>
    </message>
    <message>
        <source>The item has no control points.</source>
        <translation>Položka nemá žádné řídicí body.</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Vrcholy</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number.</source>
        <translation>„%1“ není číslo.</translation>
    </message>
    <message>
        <source>Lifted</source>
        <translation>Zdvižené</translation>
    </message>
    <message>
        <source>Points of the lifted space of 000 §2: x, y, then the extra coordinates of the lifting, the homogeneous 1 implied. Commas between coordinates, &apos;;&apos; between points.</source>
        <translation>Body zdviženého prostoru podle 000 §2: x, y a poté dodatečné souřadnice zdvižení, homogenní 1 se doplní. Souřadnice oddělujte čárkami, body znakem &apos;;&apos;.</translation>
    </message>
    <message>
        <source>Deterministic</source>
        <translation>Deterministický</translation>
    </message>
    <message>
        <source>Random (chaos game)</source>
        <translation>Náhodný (hra chaosu)</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Režim</translation>
    </message>
    <message>
        <source>Algorithm</source>
        <translation>Algoritmus</translation>
    </message>
    <message>
        <source>Deterministic iteration draws F^k(X0) at the depth k; random iteration plays the chaos game with the samples</source>
        <translation>Deterministická iterace kreslí F^k(X0) v hloubce k; náhodná iterace hraje hru chaosu s daným počtem vzorků</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Hloubka</translation>
    </message>
    <message>
        <source>The level k of F^k(X0): N^k images of the start set, at most 2^31</source>
        <translation>Úroveň k v F^k(X0): N^k obrazů počáteční množiny, nejvýše 2^31</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>Vzorky</translation>
    </message>
    <message>
        <source>Points of the chaos game</source>
        <translation>Počet bodů hry chaosu</translation>
    </message>
    <message>
        <source>Probabilities</source>
        <translation>Pravděpodobnosti</translation>
    </message>
    <message>
        <source>One weight per map for the chaos game; none: uniform</source>
        <translation>Jedna váha pro každé zobrazení ve hře chaosu; žádné: rovnoměrně</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Semínko</translation>
    </message>
    <message>
        <source>The chaos game&apos;s random stream: the same seed, the same picture</source>
        <translation>Náhodná posloupnost hry chaosu: stejné semínko, stejný obrázek</translation>
    </message>
    <message>
        <source>%1 has no point set %2</source>
        <translation>%1 nemá sadu bodů %2</translation>
    </message>
    <message>
        <source>%1: its scheme fixes the number of points at %2, got %3</source>
        <translation>%1: schéma položky pevně určuje počet bodů %2, zadáno %3</translation>
    </message>
    <message>
        <source>%1: %2 points is more than the %3 a point set may have</source>
        <translation>%1: počet bodů %2 přesahuje nejvyšší možný počet bodů v sadě (%3)</translation>
    </message>
    <message>
        <source>every point must have finite coordinates</source>
        <translation>všechny body musí mít konečné souřadnice</translation>
    </message>
    <message>
        <source>Set the points of %1</source>
        <translation>Nastavit body položky %1</translation>
    </message>
    <message>
        <source>the points of %1 were refused</source>
        <translation>body položky %1 byly odmítnuty</translation>
    </message>
    <message>
        <source>the start set &quot;net&quot; (control points of the net by index) is for items whose IFS is built from one control net (curves, surfaces, fractals with control points); this item: %1</source>
        <translation>počáteční množina „net“ (body řídicí sítě podle indexu) je jen pro položky, jejichž IFS vzniká z jedné řídicí sítě (křivky, plochy, fraktály s řídicími body); tato položka: %1</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2; this item has %3 control points (indices 0 to %4)</source>
        <translation>bod sítě %1 počáteční množiny má index %2; tato položka má %3 řídicích bodů (indexy 0 až %4)</translation>
    </message>
    <message>
        <source>Net points</source>
        <translation>Body sítě</translation>
    </message>
    <message>
        <source>The set X0 deterministic iteration starts from; drag its vertices in the attractor view. Lifted points are points of the lifted space of 000 §2; vertex limits, a mesh&apos;s vertices&apos; limit positions; net points, control points by index, which the set follows when they move.</source>
        <translation>Množina X0, z níž vychází deterministická iterace; její vrcholy přetáhněte v pohledu atraktoru. Zdvižené body jsou body zdviženého prostoru podle 000 §2; limitní polohy vrcholů jsou polohy, k nimž v limitě směřují vrcholy sítě; body sítě jsou řídicí body podle indexu, které množina sleduje, když se pohnou.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a net point index (an integer from 0).</source>
        <translation type="vanished">„%1“ není index bodu sítě (celé číslo od 0).</translation>
    </message>
    <message>
        <source>Control points by index, counted from 0 (commas between them): the start set is their point, segment or polygon in the lifted space, and it follows them when they move.</source>
        <translation>Řídicí body podle indexu, počítáno od 0 (oddělené čárkami): počáteční množina je jejich bod, úsečka nebo mnohoúhelník ve zdviženém prostoru a sleduje je, když se pohnou.</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2; the net has %3 points</source>
        <translation>bod sítě %1 počáteční množiny má index %2; síť má %3 bodů</translation>
    </message>
    <message>
        <source>this item has no control net to start from</source>
        <translation>tato položka nemá řídicí síť, z níž by mohla začít</translation>
    </message>
</context>
<context>
    <name>awb::AttractorRenderer</name>
    <message>
        <source>Cannot draw the attractor: %1</source>
        <translation>Atraktor nelze vykreslit: %1</translation>
    </message>
</context>
<context>
    <name>awb::AttractorView</name>
    <message>
        <source>Rendering… %1 %</source>
        <translation>Vykreslování… %1 %</translation>
    </message>
    <message>
        <source>Rendering cancelled at %1 % — press F5 to render again</source>
        <translation>Vykreslování zrušeno na %1 % — klávesou F5 spustíte vykreslení znovu</translation>
    </message>
    <message>
        <source>F^%1(X₀) has too many images to draw as vectors</source>
        <translation>F^%1(X₀) má příliš mnoho obrazů na vykreslení ve vektorové podobě</translation>
    </message>
    <message>
        <source>there is no attractor to count</source>
        <translation>není žádný atraktor, který by šlo spočítat</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonAnalysis</name>
    <message>
        <source>every long path contracts</source>
        <translation>každá dlouhá cesta je kontraktivní</translation>
    </message>
    <message>
        <source>some path does not contract</source>
        <translation>některá cesta není kontraktivní</translation>
    </message>
    <message>
        <source>not decided</source>
        <translation>nerozhodnuto</translation>
    </message>
    <message>
        <source>constrained JSR ρ = %1 exactly (invariant polytope, extremal cycle %2): %3</source>
        <translation>omezený společný spektrální poloměr ρ = %1 přesně (invariantní polytop, extremální cyklus %2): %3</translation>
    </message>
    <message>
        <source>constrained JSR ρ in [%1, %2]: %3</source>
        <translation>omezený společný spektrální poloměr ρ v [%1, %2]: %3</translation>
    </message>
    <message>
        <source>Lyapunov exponent of random iteration %1 (%2)</source>
        <translation>Ljapunovův exponent náhodné iterace %1 (%2)</translation>
    </message>
    <message>
        <source>contracts on average</source>
        <translation>v průměru kontraktivní</translation>
    </message>
    <message>
        <source>does not contract on average</source>
        <translation>v průměru není kontraktivní</translation>
    </message>
    <message>
        <source>cycle %1: ρ = %2 (%3 per arc); eigenvalues %4</source>
        <translation>cyklus %1: ρ = %2 (%3 na hranu); vlastní čísla %4</translation>
    </message>
    <message>
        <source>… and %1 more cycles</source>
        <translation>… a dalších %1 cyklů</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonGraph</name>
    <message>
        <source>Automaton graph</source>
        <translation>Graf automatu</translation>
    </message>
    <message>
        <source>No states</source>
        <translation>Žádné stavy</translation>
    </message>
    <message>
        <source>%1 pts</source>
        <translation>%1 b.</translation>
    </message>
    <message>
        <source>State %1: %2 control points%3</source>
        <translation>Stav %1: počet řídicích bodů %2%3</translation>
    </message>
    <message>
        <source>, drawn</source>
        <translation>, vykreslený</translation>
    </message>
    <message>
        <source>Arc %1: %2 → %3 (maps the space of %3 into %2)</source>
        <translation>Hrana %1: %2 → %3 (zobrazuje prostor stavu %3 do prostoru stavu %2)</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonPanel</name>
    <message>
        <source>Select a controlled IFS item to see and edit its automaton (Items &gt; Add &gt; Controlled IFS, or the example 003 Fig. 5).</source>
        <translation type="vanished">Vyberte položku řízeného IFS, abyste viděli a mohli upravit její automat (Položky &gt; Přidat &gt; Řízený IFS, nebo příklad 003 Fig. 5).</translation>
    </message>
    <message>
        <source>Drawn:</source>
        <translation>Vykreslit:</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn, or the union of all</source>
        <translation>Stav, jehož atraktor se vykresluje, nebo sjednocení všech</translation>
    </message>
    <message>
        <source>Add State</source>
        <translation>Přidat stav</translation>
    </message>
    <message>
        <source> points</source>
        <translation> bodů</translation>
    </message>
    <message>
        <source>The new state&apos;s number of control points: the dimension of its barycentric space (3: a frame triangle)</source>
        <translation>Počet řídicích bodů nového stavu: dimenze jeho barycentrického prostoru (3: rámcový trojúhelník)</translation>
    </message>
    <message>
        <source>Remove State</source>
        <translation>Odebrat stav</translation>
    </message>
    <message>
        <source>Add Arc</source>
        <translation>Přidat hranu</translation>
    </message>
    <message>
        <source>A new arc leaving the selected state (into itself; pick its target below)</source>
        <translation>Nová hrana vycházející z vybraného stavu (do něj samého; cíl vyberte níže)</translation>
    </message>
    <message>
        <source>Remove Arc</source>
        <translation>Odebrat hranu</translation>
    </message>
    <message>
        <source>Click a state or an arc to edit it.</source>
        <translation>Kliknutím na stav nebo hranu je upravíte.</translation>
    </message>
    <message>
        <source>State name</source>
        <translation>Název stavu</translation>
    </message>
    <message>
        <source>Arc name</source>
        <translation>Název hrany</translation>
    </message>
    <message>
        <source>From → to</source>
        <translation>Odkud → kam</translation>
    </message>
    <message>
        <source>The arc&apos;s relative probability among the arcs leaving its state (random iteration)</source>
        <translation>Relativní pravděpodobnost hrany mezi hranami vycházejícími z jejího stavu (náhodná iterace)</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Váha</translation>
    </message>
    <message>
        <source>Matrix S (rows sum to 1)</source>
        <translation>Matice S (součty řádků jsou 1)</translation>
    </message>
    <message>
        <source>Plane affine map</source>
        <translation>Afinní zobrazení roviny</translation>
    </message>
    <message>
        <source>Piece of a curve scheme</source>
        <translation>Úsek schématu křivky</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Zobrazení</translation>
    </message>
    <message>
        <source>S: a row per control point of the target state, a column per control point of the source; numbers like 1/3 are read exactly</source>
        <translation>S: jeden řádek pro každý řídicí bod cílového stavu, jeden sloupec pro každý řídicí bod zdrojového stavu; čísla jako 1/3 se načítají přesně</translation>
    </message>
    <message>
        <source>Apply Matrix</source>
        <translation>Použít matici</translation>
    </message>
    <message>
        <source>Apply Affine Map</source>
        <translation>Použít afinní zobrazení</translation>
    </message>
    <message>
        <source>x ↦ x A + b, taking the target state&apos;s frame triangle into the plane of the source&apos;s; kept as its matrix</source>
        <translation>x ↦ x A + b, převádí rámcový trojúhelník cílového stavu do roviny rámcového trojúhelníku zdrojového stavu; uloží se jako jeho matice</translation>
    </message>
    <message>
        <source>Bézier (de Casteljau at 1/2)</source>
        <translation>Bézier (de Casteljau v 1/2)</translation>
    </message>
    <message>
        <source>Uniform B-spline</source>
        <translation>Uniformní B-spline</translation>
    </message>
    <message>
        <source>End-interpolating B-spline</source>
        <translation>B-spline interpolující koncové body</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Four-point</source>
        <translation>Čtyřbodové</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Stupeň</translation>
    </message>
    <message>
        <source>Piece S_i, i =</source>
        <translation>Úsek S_i, i =</translation>
    </message>
    <message>
        <source>Apply Scheme Piece</source>
        <translation>Použít úsek schématu</translation>
    </message>
    <message>
        <source>The analysis of a controlled IFS item: its constrained joint spectral radius, its cycles&apos; spectra and the Lyapunov exponent of random iteration.</source>
        <translation>Analýza položky řízeného IFS: její omezený společný spektrální poloměr, spektra jejích cyklů a Ljapunovův exponent náhodné iterace.</translation>
    </message>
    <message>
        <source>All states</source>
        <translation>Všechny stavy</translation>
    </message>
    <message>
        <source>Analysing the automaton…</source>
        <translation>Analyzuje se automat…</translation>
    </message>
    <message>
        <source>Automaton of %1</source>
        <translation>Automat položky %1</translation>
    </message>
    <message>
        <source>%1 control points (its barycentric space), %2 arcs leave it, %3 arrive. Drag its control points in the attractor view.</source>
        <translation>Řídicí body: %1 (jeho barycentrický prostor), vycházející hrany: %2, přicházející hrany: %3. Jeho řídicí body můžete přetahovat v pohledu atraktoru.</translation>
    </message>
    <message>
        <source>S is %1 × %2: a row per point of %3, a column per point of %4. It maps the space of %3 into that of %4.</source>
        <translation>S má rozměr %1 × %2: jeden řádek pro každý bod stavu %3, jeden sloupec pro každý bod stavu %4. Zobrazuje prostor stavu %3 do prostoru stavu %4.</translation>
    </message>
    <message>
        <source>no controlled IFS item is selected</source>
        <translation>není vybrána žádná položka řízeného IFS</translation>
    </message>
    <message>
        <source>row %1, column %2 of the matrix is not a number: %3</source>
        <translation>řádek %1, sloupec %2 matice není číslo: %3</translation>
    </message>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 není číslo</translation>
    </message>
    <message>
        <source>Select a controlled IFS item to see and edit its automaton (Item &gt; Add &gt; Controlled IFS, or the example 003 Fig. 5).</source>
        <translation>Vyberte položku řízeného IFS, abyste viděli a mohli upravit její automat (Položka &gt; Přidat &gt; Řízený IFS, nebo příklad 003 Fig. 5).</translation>
    </message>
</context>
<context>
    <name>awb::BcifsJunctionItem</name>
    <message>
        <source>Junction</source>
        <translation>Napojení</translation>
    </message>
    <message>
        <source>Change junction of %1</source>
        <translation>Změnit napojení položky %1</translation>
    </message>
    <message>
        <source>e = %1, p = %2 (column sums). %3</source>
        <translation>e = %1, p = %2 (součty sloupců). %3</translation>
    </message>
    <message>
        <source>a junction is drawn by an automaton, not by one lifted IFS</source>
        <translation>napojení je kresleno automatem, ne jedním zdviženým IFS</translation>
    </message>
    <message>
        <source>Cubic–quadratic (003 §4.1)</source>
        <translation>Kubicko-kvadratické (003 §4.1)</translation>
    </message>
    <message>
        <source>Refined, with handles (003 §5)</source>
        <translation>Zjemněné, s úchyty (003 §5)</translation>
    </message>
    <message>
        <source>Last column (a, b, c, d, e) of T^l; e = 1 − a − b − c − d (003 §4.1)</source>
        <translation>Poslední sloupec (a, b, c, d, e) matice T^l; e = 1 − a − b − c − d (003 §4.1)</translation>
    </message>
    <message>
        <source>First column (k, l, m, n, p) of T^r; p = 1 − k − l − m − n (003 §4.1)</source>
        <translation>První sloupec (k, l, m, n, p) matice T^r; p = 1 − k − l − m − n (003 §4.1)</translation>
    </message>
    <message>
        <source>Left eigenvalue j</source>
        <translation>Levé vlastní číslo j</translation>
    </message>
    <message>
        <source>Tangent eigenvalue of T^il (003 §5)</source>
        <translation>Tečné vlastní číslo matice T^il (003 §5)</translation>
    </message>
    <message>
        <source>Right eigenvalue r</source>
        <translation>Pravé vlastní číslo r</translation>
    </message>
    <message>
        <source>Tangent eigenvalue of T^ir (003 §5)</source>
        <translation>Tečné vlastní číslo matice T^ir (003 §5)</translation>
    </message>
    <message>
        <source>BCIFS junction curve</source>
        <translation>Křivka napojení BCIFS</translation>
    </message>
    <message>
        <source>Left cubic</source>
        <translation>Levá kubika</translation>
    </message>
    <message>
        <source>Right quadratic</source>
        <translation>Pravá kvadratika</translation>
    </message>
    <message>
        <source>Handles</source>
        <translation>Úchyty</translation>
    </message>
</context>
<context>
    <name>awb::BezierUnionItem</name>
    <message>
        <source>Bézier union</source>
        <translation>Sjednocení Bézierových křivek</translation>
    </message>
    <message>
        <source>%1 split parameters for %2 curves</source>
        <translation type="vanished">počet parametrů dělení (%1) neodpovídá počtu křivek (%2)</translation>
    </message>
    <message>
        <source>Change Bézier union %1</source>
        <translation>Změnit sjednocení Bézierových křivek %1</translation>
    </message>
    <message>
        <source>curve %1: %2</source>
        <translation>křivka %1: %2</translation>
    </message>
    <message>
        <source>curves drawn in the lifted space of 000 §2: %1</source>
        <translation>křivky kreslené ve zdviženém prostoru podle 000 §2: %1</translation>
    </message>
    <message>
        <source>every composition of %1 maps contracts (factor %2): the dusty fractal of 002 §6 is the unique attractor</source>
        <translation>každé složení %1 zobrazení je kontrakce (koeficient %2): prachový fraktál z 002 §6 je jediný atraktor</translation>
    </message>
    <message>
        <source>no contraction was proven (best bound %1 at length %2): the picture may not be an attractor</source>
        <translation>kontraktivita nebyla prokázána (nejlepší odhad %1 pro délku %2): obrázek nemusí být atraktorem</translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="vanished">chybí</translation>
    </message>
    <message>
        <source>expected a non-empty array of curves {&quot;control_points&quot;: [...], &quot;u&quot;: number}</source>
        <translation>očekáváno neprázdné pole křivek {&quot;control_points&quot;: [...], &quot;u&quot;: číslo}</translation>
    </message>
    <message>
        <source>expected an object with &quot;control_points&quot; and &quot;u&quot;</source>
        <translation>očekáván objekt s &quot;control_points&quot; a &quot;u&quot;</translation>
    </message>
    <message>
        <source>Union</source>
        <translation>Sjednocení</translation>
    </message>
    <message>
        <source>Exact union (block IFS, 000 §2.2)</source>
        <translation>Přesné sjednocení (blokový IFS, 000 §2.2)</translation>
    </message>
    <message>
        <source>All maps together (dusty fractal, 002 §6)</source>
        <translation>Všechna zobrazení dohromady (prachový fraktál, 002 §6)</translation>
    </message>
    <message>
        <source>Split parameter u</source>
        <translation>Parametr dělení u</translation>
    </message>
    <message>
        <source>Curve %1</source>
        <translation>Křivka %1</translation>
    </message>
    <message>
        <source>de Casteljau split at u, 0 &lt; u &lt; 1 (002 eqs. (9)-(10)); the curve is the same for every u, the IFS is not</source>
        <translation>de Casteljauovo dělení v bodě u, 0 &lt; u &lt; 1 (002 eqs. (9)-(10)); křivka je pro každé u stejná, IFS nikoli</translation>
    </message>
    <message>
        <source>Union of Bézier curves</source>
        <translation>Sjednocení Bézierových křivek</translation>
    </message>
    <message>
        <source>Curves</source>
        <translation>Křivky</translation>
    </message>
    <message>
        <source>Each curve&apos;s control points and split parameter u</source>
        <translation>Řídicí body každé křivky a její parametr dělení u</translation>
    </message>
</context>
<context>
    <name>awb::BezierUnionSpec</name>
    <message>
        <source>a union needs at least one curve</source>
        <translation>sjednocení vyžaduje alespoň jednu křivku</translation>
    </message>
    <message>
        <source>the split parameter u = %1 must satisfy 0 &lt; u &lt; 1 (002 §3)</source>
        <translation>parametr dělení u = %1 musí splňovat 0 &lt; u &lt; 1 (002 §3)</translation>
    </message>
    <message>
        <source>%1 split parameters for %2 curves</source>
        <translation>počet parametrů dělení (%1) neodpovídá počtu křivek (%2)</translation>
    </message>
</context>
<context>
    <name>awb::CharacteristicMapView</name>
    <message>
        <source>The characteristic map: the n faces around the vertex under the two eigenvectors of the subdominant eigenvalue. Cells where the Jacobian changes sign are red.</source>
        <translation>Charakteristické zobrazení: n stěn kolem vrcholu zobrazených pomocí dvou vlastních vektorů subdominantního vlastního čísla. Buňky, v nichž jakobián mění znaménko, jsou červené.</translation>
    </message>
    <message>
        <source>Click an extraordinary vertex in the 3D view to see its characteristic map.</source>
        <translation>Klikněte na mimořádný vrchol ve 3D pohledu a zobrazí se jeho charakteristické zobrazení.</translation>
    </message>
    <message>
        <source>n = %1: regular, %2</source>
        <translation>n = %1: regulární, %2</translation>
    </message>
    <message>
        <source>injective</source>
        <translation>injektivní</translation>
    </message>
    <message>
        <source>not injective</source>
        <translation>neinjektivní</translation>
    </message>
    <message>
        <source>n = %1: the Jacobian changes sign in %2 cells</source>
        <translation>n = %1: jakobián mění znaménko v %2 buňkách</translation>
    </message>
</context>
<context>
    <name>awb::CheckedSpinBox</name>
    <message>
        <source>“%1” is not a whole number.</source>
        <translation>„%1“ není celé číslo.</translation>
    </message>
    <message>
        <source>%1 is outside %2 … %3.</source>
        <translation>%1 leží mimo %2 … %3.</translation>
    </message>
</context>
<context>
    <name>awb::CifsItem</name>
    <message>
        <source>Fern of gaskets</source>
        <translation>Kapradina ze Sierpińského trojúhelníků</translation>
    </message>
    <message>
        <source>Change automaton of %1</source>
        <translation>Změnit automat položky %1</translation>
    </message>
    <message>
        <source>the frame needs exactly 3 points, got %1</source>
        <translation type="vanished">rámec vyžaduje přesně 3 body, zadáno %1</translation>
    </message>
    <message>
        <source>a controlled IFS has no single lifted IFS</source>
        <translation>řízený IFS nemá jediný zdvižený IFS</translation>
    </message>
    <message>
        <source>Arc T%1 of the fern leads into the Sierpiński state (003 §2.2, Fig. 4).</source>
        <translation type="vanished">Hrana T%1 kapradiny vede do Sierpińského stavu (003 §2.2, Fig. 4).</translation>
    </message>
    <message>
        <source>Automaton</source>
        <translation>Automat</translation>
    </message>
    <message>
        <source>Redirected arc</source>
        <translation type="vanished">Přesměrovaná hrana</translation>
    </message>
    <message>
        <source>The fern map (0 stem, 1 main frond, 2 left, 3 right leaflet) whose arc leads into the Sierpiński state (003 Fig. 4)</source>
        <translation type="vanished">Zobrazení kapradiny (0 stonek, 1 hlavní list, 2 levý, 3 pravý lístek), jehož hrana vede do Sierpińského stavu (003 Fig. 4)</translation>
    </message>
    <message>
        <source>Drawn state</source>
        <translation>Kreslený stav</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn</source>
        <translation type="vanished">Stav, jehož atraktor se kreslí</translation>
    </message>
    <message>
        <source>Controlled IFS</source>
        <translation>Řízený IFS</translation>
    </message>
    <message>
        <source>Fern of gaskets (003 Fig. 4)</source>
        <translation type="vanished">Kapradina ze Sierpińského trojúhelníků (003 Fig. 4)</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation type="vanished">Rámec</translation>
    </message>
    <message>
        <source>a controlled IFS draws its arcs by their own weights (&quot;arcs&quot;): leave the algorithm&apos;s probabilities empty</source>
        <translation>řízený IFS losuje své hrany podle jejich vlastních vah (&quot;arcs&quot;): pravděpodobnosti algoritmu ponechte prázdné</translation>
    </message>
    <message>
        <source>arcs between states of different dimensions have rectangular matrices: see the automaton&apos;s analysis</source>
        <translation>hrany mezi stavy různých dimenzí mají obdélníkové matice: viz analýzu automatu</translation>
    </message>
    <message>
        <source>The union of the attractors of the automaton&apos;s %1 states (003 §2.2).</source>
        <translation>Sjednocení atraktorů %1 stavů automatu (003 §2.2).</translation>
    </message>
    <message>
        <source>The attractor of state %1 of the automaton (003 §2.2).</source>
        <translation>Atraktor stavu %1 automatu (003 §2.2).</translation>
    </message>
    <message>
        <source>States</source>
        <translation>Stavy</translation>
    </message>
    <message>
        <source>Each state&apos;s name and control points (its barycentric space)</source>
        <translation>Název a řídicí body každého stavu (jeho barycentrický prostor)</translation>
    </message>
    <message>
        <source>Arcs</source>
        <translation>Hrany</translation>
    </message>
    <message>
        <source>Each arc&apos;s states and matrix S (a row per point of the state it leads to, rows summing to 1) and weight</source>
        <translation>Stavy, matice S (jeden řádek pro každý bod stavu, do kterého hrana vede, součty řádků jsou 1) a váha každé hrany</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn, or the union of all</source>
        <translation>Stav, jehož atraktor se vykresluje, nebo sjednocení všech</translation>
    </message>
</context>
<context>
    <name>awb::CifsSpec</name>
    <message>
        <source>the redirected fern arc must be 0 … 3 (T0 … T3), got %1</source>
        <translation type="vanished">přesměrovaná hrana kapradiny musí být 0 … 3 (T0 … T3), zadáno %1</translation>
    </message>
    <message>
        <source>no state &quot;%1&quot;; the states are &quot;%2&quot;</source>
        <translation type="vanished">stav „%1“ neexistuje; stavy jsou „%2“</translation>
    </message>
    <message>
        <source>expected a matrix: a non-empty array of rows</source>
        <translation>očekávána matice: neprázdné pole řádků</translation>
    </message>
    <message>
        <source>a %1 x %2 matrix: a state has at most %3 points</source>
        <translation>matice %1 x %2: stav má nejvýše %3 bodů</translation>
    </message>
    <message>
        <source>expected a row of %1 numbers, like row 1</source>
        <translation>očekáván řádek s %1 čísly, jako řádek 1</translation>
    </message>
    <message>
        <source>no state %1; the states are %2</source>
        <translation>stav %1 neexistuje; stavy jsou %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádné</translation>
    </message>
    <message>
        <source>expected a state&apos;s name</source>
        <translation>očekáván název stavu</translation>
    </message>
    <message>
        <source>missing: give the arc&apos;s map as &quot;matrix&quot;, &quot;columns&quot;, &quot;affine&quot; or &quot;scheme&quot;</source>
        <translation>chybí: zadejte zobrazení hrany jako &quot;matrix&quot;, &quot;columns&quot;, &quot;affine&quot; nebo &quot;scheme&quot;</translation>
    </message>
    <message>
        <source>give the arc&apos;s map one way, not as %1</source>
        <translation>zadejte zobrazení hrany jedním způsobem, ne jako %1</translation>
    </message>
    <message>
        <source> and </source>
        <translation> a </translation>
    </message>
    <message>
        <source>a plane affine map needs both states to have 3 control points (a frame triangle): %1 has %2, %3 has %4</source>
        <translation>afinní zobrazení roviny vyžaduje, aby oba stavy měly 3 řídicí body (rámcový trojúhelník): %1 má %2, %3 má %4</translation>
    </message>
    <message>
        <source>expected {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</source>
        <translation>očekáváno {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</translation>
    </message>
    <message>
        <source>A must be 2 x 2 and b two numbers</source>
        <translation>A musí mít rozměr 2 x 2 a b musí být dvě čísla</translation>
    </message>
    <message>
        <source>expected a curve scheme, as a curve item&apos;s &quot;scheme&quot;</source>
        <translation>očekáváno schéma křivky, jako &quot;scheme&quot; položky křivky</translation>
    </message>
    <message>
        <source>a scheme&apos;s matrix is square: %1 has %2 points, %3 has %4</source>
        <translation>matice schématu je čtvercová: %1 má %2 bodů, %3 má %4</translation>
    </message>
    <message>
        <source>an automaton needs at least one state</source>
        <translation>automat potřebuje alespoň jeden stav</translation>
    </message>
    <message>
        <source>%1 states: at most %2</source>
        <translation>%1 stavů: nejvýše %2</translation>
    </message>
    <message>
        <source>a state needs a name</source>
        <translation>stav musí mít název</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names all states; call the state otherwise</source>
        <translation>&quot;%1&quot; označuje všechny stavy; pojmenujte stav jinak</translation>
    </message>
    <message>
        <source>two states are called %1</source>
        <translation>dva stavy se jmenují %1</translation>
    </message>
    <message>
        <source>a state needs 1 to %1 control points, got %2</source>
        <translation>stav potřebuje 1 až %1 řídicích bodů, zadáno %2</translation>
    </message>
    <message>
        <source>state %1 has a control point that is not finite</source>
        <translation>stav %1 má řídicí bod, který není konečný</translation>
    </message>
    <message>
        <source>%1 arcs: at most %2 (addresses are bytes)</source>
        <translation>%1 hran: nejvýše %2 (adresy jsou bajty)</translation>
    </message>
    <message>
        <source>an arc needs a name</source>
        <translation>hrana musí mít název</translation>
    </message>
    <message>
        <source>two arcs are called %1</source>
        <translation>dvě hrany se jmenují %1</translation>
    </message>
    <message>
        <source>arc %1 leads between states that do not exist</source>
        <translation>hrana %1 vede mezi stavy, které neexistují</translation>
    </message>
    <message>
        <source>arc %1 has a %2 x %3 matrix; from %4 (%5 points) to %6 (%7 points) it must be %7 x %5: a row per point of %6</source>
        <translation>hrana %1 má matici %2 x %3; ze stavu %4 (%5 bodů) do stavu %6 (%7 bodů) musí mít rozměr %7 x %5: jeden řádek pro každý bod stavu %6</translation>
    </message>
    <message>
        <source>arc %1 has a matrix entry that is not finite</source>
        <translation>hrana %1 má prvek matice, který není konečný</translation>
    </message>
    <message>
        <source>row %1 of arc %2 sums to %3, not 1: the map would not keep barycentric coordinates</source>
        <translation>součet řádku %1 hrany %2 je %3, nikoli 1: zobrazení by nezachovávalo barycentrické souřadnice</translation>
    </message>
    <message>
        <source>the weight of arc %1 must be a number &gt; 0</source>
        <translation>váha hrany %1 musí být číslo &gt; 0</translation>
    </message>
    <message>
        <source>no state %1 to draw; the states are %2</source>
        <translation>stav %1 k vykreslení neexistuje; stavy jsou %2</translation>
    </message>
    <message>
        <source>expected a non-empty array of states {&quot;name&quot;: text, &quot;control_points&quot;: [...]}</source>
        <translation>očekáváno neprázdné pole stavů {&quot;name&quot;: text, &quot;control_points&quot;: [...]}</translation>
    </message>
    <message>
        <source>expected an object with &quot;name&quot; and &quot;control_points&quot;</source>
        <translation>očekáván objekt s &quot;name&quot; a &quot;control_points&quot;</translation>
    </message>
    <message>
        <source>unknown field of a state</source>
        <translation>neznámé pole stavu</translation>
    </message>
    <message>
        <source>expected an array of arcs {&quot;name&quot;, &quot;from&quot;, &quot;to&quot;, &quot;matrix&quot;}</source>
        <translation>očekáváno pole hran {&quot;name&quot;, &quot;from&quot;, &quot;to&quot;, &quot;matrix&quot;}</translation>
    </message>
    <message>
        <source>expected an object with &quot;from&quot;, &quot;to&quot; and the arc&apos;s map</source>
        <translation>očekáván objekt s &quot;from&quot;, &quot;to&quot; a zobrazením hrany</translation>
    </message>
    <message>
        <source>unknown field of an arc</source>
        <translation>neznámé pole hrany</translation>
    </message>
    <message>
        <source>All states</source>
        <translation>Všechny stavy</translation>
    </message>
</context>
<context>
    <name>awb::ComplexBezierItem</name>
    <message>
        <source>Complex Bézier</source>
        <translation>Komplexní Bézierova křivka</translation>
    </message>
    <message>
        <source>the parameter t must be a finite complex number</source>
        <translation>parametr t musí být konečné komplexní číslo</translation>
    </message>
    <message>
        <source>Change t of %1</source>
        <translation>Změnit t položky %1</translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="vanished">chybí</translation>
    </message>
    <message>
        <source>expected [re, im]</source>
        <translation>očekáváno [re, im]</translation>
    </message>
    <message>
        <source>Split parameter t</source>
        <translation>Parametr dělení t</translation>
    </message>
    <message>
        <source>Curve</source>
        <translation>Křivka</translation>
    </message>
    <message>
        <source>de Casteljau split at a complex t; inside both discs |t| &lt; 1 and |1 − t| &lt; 1 the curve is a fractal (004 §3.7, Fig. 3.3)</source>
        <translation>de Casteljauovo dělení v komplexním t; uvnitř obou kruhů |t| &lt; 1 a |1 − t| &lt; 1 je křivka fraktál (004 §3.7, Fig. 3.3)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid value for %2</source>
        <translation type="vanished">„%1“ není platná hodnota pro %2</translation>
    </message>
    <message>
        <source>Complex Bézier curve</source>
        <translation>Komplexní Bézierova křivka</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Řídicí body</translation>
    </message>
    <message>
        <source>Scaled coordinates g(z, 1/(2y)) = Re z + i Im z / (2y), y = %1 (004 eq. (3.40)): as y → 0 the curve approaches the Takagi graph x + i T(x) (Thm 3.7.3, Figs. 3.6–3.8). %2</source>
        <translation>Škálované souřadnice g(z, 1/(2y)) = Re z + i Im z / (2y), y = %1 (004 eq. (3.40)): pro y → 0 se křivka blíží grafu Takagiho funkce x + i T(x) (Thm 3.7.3, Figs. 3.6–3.8). %2</translation>
    </message>
    <message>
        <source>Scaled coordinates apply to t = 1/2 + iy with y ≠ 0 and control points on the real axis (004 Thm 3.7.3); drawn unscaled. %1</source>
        <translation>Škálované souřadnice platí pro t = 1/2 + iy s y ≠ 0 a řídicími body na reálné ose (004 Thm 3.7.3); vykresleno bez škálování. %1</translation>
    </message>
    <message>
        <source>Change scaled coordinates of %1</source>
        <translation>Změnit škálované souřadnice položky %1</translation>
    </message>
    <message>
        <source>Scaled coordinates g(z, 1/(2y))</source>
        <translation>Škálované souřadnice g(z, 1/(2y))</translation>
    </message>
    <message>
        <source>Draw Re z + i Im z / (2y) for t = 1/2 + iy: the coordinates of 004 Thm 3.7.3 and Figs. 3.6–3.8, where the curve approaches the Takagi graph</source>
        <translation>Vykreslit Re z + i Im z / (2y) pro t = 1/2 + iy: souřadnice z 004 Thm 3.7.3 a Figs. 3.6–3.8, v nichž se křivka blíží grafu Takagiho funkce</translation>
    </message>
</context>
<context>
    <name>awb::ComplexPlanePicker</name>
    <message>
        <source>Drag t in the complex plane. The attractor exists inside the lens where |t| &lt; 1 and |1 − t| &lt; 1 (both maps contract, 004 Fig. 3.3).</source>
        <translation>Táhněte t v komplexní rovině. Atraktor existuje uvnitř čočky, kde |t| &lt; 1 a |1 − t| &lt; 1 (obě zobrazení jsou kontrakce, 004 Fig. 3.3).</translation>
    </message>
</context>
<context>
    <name>awb::ControlPointEdits</name>
    <message>
        <source>There is no such point set.</source>
        <translation>Taková sada bodů neexistuje.</translation>
    </message>
    <message>
        <source>%1 (%2) has a fixed number of control points.</source>
        <translation>%1 (%2) má pevný počet řídicích bodů.</translation>
    </message>
    <message>
        <source>A Bézier curve of degree %1 is refused: %2</source>
        <translation>Bézierova křivka stupně %1 byla odmítnuta: %2</translation>
    </message>
    <message>
        <source>There is no point %1.</source>
        <translation>Bod %1 neexistuje.</translation>
    </message>
    <message>
        <source>Insert control point %1 into %2</source>
        <translation>Vložit řídicí bod %1 do položky %2</translation>
    </message>
    <message>
        <source>No control point is selected.</source>
        <translation>Není vybrán žádný řídicí bod.</translation>
    </message>
    <message>
        <source>%1 needs at least %2 control points.</source>
        <translation>%1: počet řídicích bodů musí být alespoň %2.</translation>
    </message>
    <message>
        <source>Delete control point %1 of %2</source>
        <translation>Odstranit řídicí bod %1 položky %2</translation>
    </message>
    <message>
        <source>Delete %1 control points of %2</source>
        <translation>Odstranit řídicí body (%1) položky %2</translation>
    </message>
</context>
<context>
    <name>awb::DensityFile</name>
    <message>
        <source>cannot write %1: the picture is empty</source>
        <translation>nelze zapsat %1: obrázek je prázdný</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>nelze číst %1: %2</translation>
    </message>
    <message>
        <source>cannot write %1: not enough memory</source>
        <translation>nelze zapsat %1: nedostatek paměti</translation>
    </message>
    <message>
        <source>%1; alpha = log(1 + hits) / log(1 + %2); world %3 %4 %5 %6</source>
        <translation>%1; alpha = log(1 + zásahy) / log(1 + %2); svět %3 %4 %5 %6</translation>
    </message>
</context>
<context>
    <name>awb::EigenvaluePlotItem</name>
    <message>
        <source>Eigenvalues</source>
        <translation>Vlastní čísla</translation>
    </message>
    <message>
        <source>S_i, the subdivision matrices</source>
        <translation>S_i, subdivizní matice</translation>
    </message>
    <message>
        <source>A_i, the linear parts of M_i</source>
        <translation>A_i, lineární části M_i</translation>
    </message>
    <message>
        <source>M_i = P⁻¹S_iP, the lifted maps</source>
        <translation>M_i = P⁻¹S_iP, zdvižená zobrazení</translation>
    </message>
    <message>
        <source>Change the source of %1</source>
        <translation>Změnit zdroj položky %1</translation>
    </message>
    <message>
        <source>Analyse the matrices %1 in %2</source>
        <translation>Analyzovat matice %1 v položce %2</translation>
    </message>
    <message>
        <source>M_i is defined only for a lifted subdivision IFS</source>
        <translation>M_i je definováno jen pro zdvižený subdivizní IFS</translation>
    </message>
    <message>
        <source>no item is chosen to analyse</source>
        <translation>není vybrána žádná položka k analýze</translation>
    </message>
    <message>
        <source>there is no item called &quot;%1&quot;</source>
        <translation>položka „%1“ neexistuje</translation>
    </message>
    <message>
        <source>&quot;%1&quot; (%2) has no matrices to analyse</source>
        <translation>„%1“ (%2) nemá žádné matice k analýze</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be computed: %2</source>
        <translation>„%1“ nelze vypočítat: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no matrices %2: %3</source>
        <translation>„%1“ nemá matice %2: %3</translation>
    </message>
    <message>
        <source>Eigenvalue plot</source>
        <translation>Graf vlastních čísel</translation>
    </message>
    <message>
        <source>Analyse the centre of face %1 in %2</source>
        <translation>Analyzovat střed stěny %1 v položce %2</translation>
    </message>
    <message>
        <source>Analyse vertex %1 in %2</source>
        <translation>Analyzovat vrchol %1 v položce %2</translation>
    </message>
    <message>
        <source>Analyse the mesh&apos;s matrices in %1</source>
        <translation>Analyzovat matice sítě v položce %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a mesh: it has no extraordinary vertices</source>
        <translation>„%1“ není síť: nemá mimořádné vrcholy</translation>
    </message>
    <message>
        <source>the centre of face %1 of &quot;%2&quot; is not an extraordinary vertex</source>
        <translation>střed stěny %1 položky „%2“ není mimořádný vrchol</translation>
    </message>
    <message>
        <source>vertex %1 of &quot;%2&quot; is not an extraordinary vertex</source>
        <translation>vrchol %1 položky „%2“ není mimořádný vrchol</translation>
    </message>
    <message>
        <source>an extraordinary vertex has its local subdivision matrix S only</source>
        <translation>mimořádný vrchol má jen svou lokální matici subdivize S</translation>
    </message>
    <message>
        <source>expected a vertex or face number (0-based)</source>
        <translation>očekáváno číslo vrcholu nebo stěny (číslováno od 0)</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(žádná)</translation>
    </message>
    <message>
        <source>%1 (missing)</source>
        <translation>%1 (chybí)</translation>
    </message>
    <message>
        <source>(the mesh&apos;s matrices)</source>
        <translation>(matice sítě)</translation>
    </message>
    <message>
        <source>vertex %1 (n = %2)</source>
        <translation>vrchol %1 (n = %2)</translation>
    </message>
    <message>
        <source>centre of face %1 (n = %2)</source>
        <translation>střed stěny %1 (n = %2)</translation>
    </message>
    <message>
        <source>centre of face %1 (missing)</source>
        <translation>střed stěny %1 (chybí)</translation>
    </message>
    <message>
        <source>vertex %1 (missing)</source>
        <translation>vrchol %1 (chybí)</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Zdroj</translation>
    </message>
    <message>
        <source>The item whose matrices are analysed</source>
        <translation>Položka, jejíž matice se analyzují</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>Matice</translation>
    </message>
    <message>
        <source>S_i: the subdivision matrices (their eigenvalue 1 is affine invariance); A_i: the linear parts of the lifted maps, whose subdominant eigenvalue decides the tangents; M_i: the lifted maps themselves (003 §4, 004 §2.1)</source>
        <translation>S_i: subdivizní matice (jejich vlastní číslo 1 vyjadřuje afinní invarianci); A_i: lineární části zdvižených zobrazení, jejichž subdominantní vlastní číslo určuje tečny; M_i: samotná zdvižená zobrazení (003 §4, 004 §2.1)</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Vrchol</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Stěna</translation>
    </message>
    <message>
        <source>For a mesh surface: the extraordinary vertex whose local subdivision matrix is analysed</source>
        <translation>U plochy ze sítě: mimořádný vrchol, jehož lokální matice subdivize se analyzuje</translation>
    </message>
</context>
<context>
    <name>awb::ExactCurve</name>
    <message>
        <source>Bézier curve c([0, 1])</source>
        <translation>Bézierova křivka c([0, 1])</translation>
    </message>
    <message>
        <source>Takagi image c(x + 2iy·T(x)), y = %1 (Conj. 3.7.1)</source>
        <translation>Takagiho obraz c(x + 2iy·T(x)), y = %1 (Conj. 3.7.1)</translation>
    </message>
    <message>
        <source>exact curve: %1</source>
        <translation>přesná křivka: %1</translation>
    </message>
    <message>
        <source>Takagi graph x + i T(x), scaled (004 Thm 3.7.3)</source>
        <translation>Graf Takagiho funkce x + i T(x), škálovaný (004 Thm 3.7.3)</translation>
    </message>
</context>
<context>
    <name>awb::ExactSpinBox</name>
    <message>
        <source>“%1” is not a number (type e.g. 0.25, 1/3 or sqrt(3)/6).</source>
        <translation>„%1“ není číslo (napište např. 0.25, 1/3 nebo sqrt(3)/6).</translation>
    </message>
    <message>
        <source>%1 is outside %2 … %3.</source>
        <translation>%1 leží mimo %2 … %3.</translation>
    </message>
</context>
<context>
    <name>awb::ExampleGallery</name>
    <message>
        <source>Open Example</source>
        <translation>Otevřít příklad</translation>
    </message>
    <message>
        <source>One project per figure of the papers, and examples of meshes, masks and animations. An example opens as a copy: Save As keeps it.</source>
        <translation>Jeden projekt pro každý obrázek z článků a k tomu příklady sítí, masek a animací. Příklad se otevře jako kopie: Uložit jako ji zachová.</translation>
    </message>
    <message>
        <source>Filter: a paper (003), a figure, a word (Koch, mesh)…</source>
        <translation>Filtr: článek (003), obrázek, slovo (Koch, mesh)…</translation>
    </message>
    <message>
        <source>No examples installed</source>
        <translation>Žádné příklady nejsou nainstalovány</translation>
    </message>
</context>
<context>
    <name>awb::ExportDialog</name>
    <message>
        <source>Export Figure</source>
        <translation>Exportovat obrázek</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;LaTeX matrices (*.tex)</source>
        <translation type="vanished">Obrázek PNG (*.png);;Kresba SVG (*.svg);;Dokument PDF (*.pdf);;Matice v LaTeXu (*.tex)</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;LaTeX matrices (*.tex);;OpenEXR raw density of the attractor, float32 hits per pixel (*.exr)</source>
        <translation>Obrázek PNG (*.png);;Kresba SVG (*.svg);;Dokument PDF (*.pdf);;Matice v LaTeXu (*.tex);;Surová hustota atraktoru v OpenEXR, zásahy na pixel jako float32 (*.exr)</translation>
    </message>
</context>
<context>
    <name>awb::FieldReader</name>
    <message>
        <source>missing</source>
        <translation>chybí</translation>
    </message>
    <message>
        <source>expected a string</source>
        <translation>očekáván řetězec</translation>
    </message>
    <message>
        <source>expected one of %1, got %2</source>
        <translation>očekávána jedna z hodnot %1, zadáno %2</translation>
    </message>
    <message>
        <source>expected an integer</source>
        <translation>očekáváno celé číslo</translation>
    </message>
    <message>
        <source>expected an integer between %1 and %2</source>
        <translation>očekáváno celé číslo mezi %1 a %2</translation>
    </message>
    <message>
        <source>expected an array of numbers</source>
        <translation>očekáváno pole čísel</translation>
    </message>
    <message>
        <source>expected an array of points [x, y, z]</source>
        <translation>očekáváno pole bodů [x, y, z]</translation>
    </message>
    <message>
        <source>expected an array of points [x, y]</source>
        <translation>očekáváno pole bodů [x, y]</translation>
    </message>
    <message>
        <source>expected an array of matrices</source>
        <translation>očekáváno pole matic</translation>
    </message>
    <message>
        <source>expected a matrix: a non-empty array of rows</source>
        <translation>očekávána matice: neprázdné pole řádků</translation>
    </message>
    <message>
        <source>expected a row: a non-empty array of numbers</source>
        <translation>očekáván řádek: neprázdné pole čísel</translation>
    </message>
    <message>
        <source>row %1 has %2 numbers, row 1 has %3</source>
        <translation>řádek %1 má počet čísel %2, řádek 1 má %3</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>očekáván objekt</translation>
    </message>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 není konečné číslo</translation>
    </message>
    <message>
        <source>%1 cannot be read as a double-precision number</source>
        <translation>%1 nelze přečíst jako číslo s dvojitou přesností</translation>
    </message>
    <message>
        <source>expected a number</source>
        <translation>očekáváno číslo</translation>
    </message>
    <message>
        <source>expected a finite number</source>
        <translation>očekáváno konečné číslo</translation>
    </message>
    <message>
        <source>expected a point [x, y, z]</source>
        <translation>očekáván bod [x, y, z]</translation>
    </message>
    <message>
        <source>expected a point [x, y]</source>
        <translation>očekáván bod [x, y]</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number (a fraction such as &quot;3/8&quot; or an expression such as &quot;(1 + sqrt(3))/8&quot; is)</source>
        <translation>&quot;%1&quot; není číslo (číslem je zlomek jako &quot;3/8&quot; nebo výraz jako &quot;(1 + sqrt(3))/8&quot;)</translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation>očekáváno true nebo false</translation>
    </message>
</context>
<context>
    <name>awb::FigureFile</name>
    <message>
        <source>cannot write %1</source>
        <translation>nelze zapsat %1</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 nelze zapsat: %2</translation>
    </message>
    <message>
        <source>the folder %1 does not exist</source>
        <translation>složka %1 neexistuje</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>je to složka</translation>
    </message>
    <message>
        <source>the file is read-only</source>
        <translation>soubor je jen pro čtení</translation>
    </message>
    <message>
        <source>cannot write %1: it is a folder</source>
        <translation>%1 nelze zapsat: je to složka</translation>
    </message>
    <message>
        <source>%1 has no suffix: name the format (.png, .svg or .pdf)</source>
        <translation>%1 nemá příponu: uveďte formát (.png, .svg nebo .pdf)</translation>
    </message>
    <message>
        <source>unknown output format &apos;.%1&apos; (use .png, .svg or .pdf)</source>
        <translation>neznámý výstupní formát „.%1“ (použijte .png, .svg nebo .pdf)</translation>
    </message>
</context>
<context>
    <name>awb::FigureSheet</name>
    <message>
        <source>yes</source>
        <translation>ano</translation>
    </message>
    <message>
        <source>no</source>
        <translation>ne</translation>
    </message>
    <message>
        <source>No item</source>
        <translation>Žádná položka</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>maps = %1</source>
        <translation>zobrazení = %1</translation>
    </message>
    <message>
        <source>control points = %1</source>
        <translation>řídicí body = %1</translation>
    </message>
    <message>
        <source>depth = %1</source>
        <translation>hloubka = %1</translation>
    </message>
    <message>
        <source>samples = %1</source>
        <translation>vzorky = %1</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more: see the Matrices dock, or copy them as LaTeX.</source>
        <translation>
            <numerusform>… a %n další: viz panel Matice, nebo je zkopírujte jako LaTeX.</numerusform>
            <numerusform>… a %n další: viz panel Matice, nebo je zkopírujte jako LaTeX.</numerusform>
            <numerusform>… a %n dalších: viz panel Matice, nebo je zkopírujte jako LaTeX.</numerusform>
        </translation>
    </message>
    <message>
        <source>Printing %1 was cancelled while the attractor was drawn.</source>
        <translation>Tisk %1 byl zrušen během kreslení atraktoru.</translation>
    </message>
    <message>
        <source>%1 (%2 × %3):</source>
        <translation>%1 (%2 × %3):</translation>
    </message>
</context>
<context>
    <name>awb::FileWriting</name>
    <message>
        <source>the folder %1 does not exist</source>
        <translation>složka %1 neexistuje</translation>
    </message>
    <message>
        <source>%1 is not a folder</source>
        <translation>%1 není složka</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>je to složka</translation>
    </message>
    <message>
        <source>the file is read-only</source>
        <translation>soubor je jen pro čtení</translation>
    </message>
    <message>
        <source>cannot create a file in the folder %1: %2</source>
        <translation>ve složce %1 nelze vytvořit soubor: %2</translation>
    </message>
    <message>
        <source>the folder %1 is read-only</source>
        <translation>složka %1 je jen pro čtení</translation>
    </message>
    <message>
        <source>the file is not open</source>
        <translation>soubor není otevřen</translation>
    </message>
</context>
<context>
    <name>awb::FlameExchange</name>
    <message>
        <source>the XML is malformed: %1</source>
        <translation type="vanished">chybně utvořené XML: %1</translation>
    </message>
    <message>
        <source>%1: the file holds no &lt;flame&gt; element</source>
        <translation type="vanished">%1: soubor neobsahuje žádný prvek &lt;flame&gt;</translation>
    </message>
    <message>
        <source>%1, line %2, column %3: </source>
        <translation>%1, řádek %2, sloupec %3: </translation>
    </message>
    <message>
        <source>flame %1</source>
        <translation>plamen %1</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;, final xform</source>
        <translation type="vanished">plamen „%1“, finální xform</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;, xform %2</source>
        <translation type="vanished">plamen „%1“, xform %2</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: &lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number</source>
        <translation type="vanished">plamen „%1“: &lt;symmetry&gt; vyžaduje kind=&quot;k&quot;, celé číslo</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: element &lt;%2&gt; ignored</source>
        <translation type="vanished">plamen „%1“: prvek &lt;%2&gt; ignorován</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos; has no xform</source>
        <translation type="vanished">plamen „%1“ nemá žádnou xform</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be 6 finite numbers</source>
        <translation type="vanished">%1=&quot;%2&quot; musí být 6 konečných čísel</translation>
    </message>
    <message>
        <source>weight=&quot;%1&quot; must be a finite number &gt;= 0</source>
        <translation type="vanished">weight=&quot;%1&quot; musí být konečné číslo &gt;= 0</translation>
    </message>
    <message>
        <source>var1=&quot;%1&quot; names no variation</source>
        <translation type="vanished">var1=&quot;%1&quot; neoznačuje žádnou variaci</translation>
    </message>
    <message>
        <source>variation %1=&quot;%2&quot; is not a number</source>
        <translation type="vanished">variace %1=&quot;%2&quot; není číslo</translation>
    </message>
    <message>
        <source>: opacity %1 not kept (every map is drawn)</source>
        <translation type="vanished">: opacity %1 nezachována (vykresluje se každé zobrazení)</translation>
    </message>
    <message>
        <source>: attribute %1=&quot;%2&quot; ignored</source>
        <translation type="vanished">: atribut %1=&quot;%2&quot; ignorován</translation>
    </message>
    <message numerus="yes">
        <source>: variation %1 dropped (non-linear)</source>
        <translation type="vanished">
            <numerusform>: variace %1 vynechána (nelineární)</numerusform>
            <numerusform>: variace %1 vynechány (nelineární)</numerusform>
            <numerusform>: variace %1 vynechány (nelineární)</numerusform>
        </translation>
    </message>
    <message>
        <source>; its affine part kept as a linear map</source>
        <translation type="vanished">; její afinní část zachována jako lineární zobrazení</translation>
    </message>
    <message>
        <source>: no variation given; taken as linear</source>
        <translation type="vanished">: nezadána žádná variace; použije se linear</translation>
    </message>
    <message>
        <source>%1: element &lt;%2&gt; ignored (animation)</source>
        <translation type="vanished">%1: prvek &lt;%2&gt; ignorován (animace)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: a &lt;color&gt; needs index=&quot;0..255&quot; and rgb=&quot;r g b&quot;</source>
        <translation type="vanished">plamen „%1“: prvek &lt;color&gt; vyžaduje index=&quot;0..255&quot; a rgb=&quot;r g b&quot;</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: the palette&apos;s hex digits are not whole colours of %2 digits</source>
        <translation type="vanished">plamen „%1“: hexadecimální číslice palety netvoří celé barvy po %2 číslicích</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: palette entry %2 is not hexadecimal</source>
        <translation type="vanished">plamen „%1“: záznam palety %2 není hexadecimální</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: the final xform is not invertible (determinant %2): dropped</source>
        <translation type="vanished">plamen „%1“: finální xform není invertovatelná (determinant %2): vynechána</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos (chaos) rows forbid some transitions; imported as the plain IFS of its maps, whose attractor contains the flame&apos;s</source>
        <translation type="vanished">plamen „%1“: jeho řádky xaos (chaos) zakazují některé přechody; importován jako prostý IFS jeho zobrazení, jehož atraktor obsahuje atraktor plamene</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos (chaos) weights are dropped: the attractor is the same, its measure differs</source>
        <translation type="vanished">plamen „%1“: jeho váhy xaos (chaos) jsou vynechány: atraktor je stejný, jeho míra se liší</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: every xform has weight 0</source>
        <translation>plamen „%1“: každá xform má váhu 0</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2 (%3)</source>
        <translation>plamen „%1“: %2 (%3)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2</source>
        <translation>plamen „%1“: %2</translation>
    </message>
    <message>
        <source>%1: the file is larger than %2 MB</source>
        <translation type="vanished">%1: soubor je větší než %2 MB</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation type="vanished">nelze přečíst %1: %2</translation>
    </message>
    <message>
        <source>%1 is an IFS of space: a flame holds maps of the plane</source>
        <translation type="vanished">%1 je IFS v prostoru: plamen obsahuje zobrazení roviny</translation>
    </message>
    <message>
        <source>the flame&apos;s frame is empty</source>
        <translation>rámec plamene je prázdný</translation>
    </message>
    <message>
        <source>: no weight given; taken as 0, as flam3 does (the map is never chosen)</source>
        <translation type="vanished">: váha není uvedena; bere se 0 jako ve flam3 (zobrazení se nikdy nevybere)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its maps do not contract, not even on average (Lyapunov exponent %2 &gt;= 0), so it has no attractor; flam3 draws it only by discarding the points that escape</source>
        <translation type="vanished">plamen &apos;%1&apos;: jeho zobrazení nejsou kontraktivní, ani v průměru (Ljapunovův exponent %2 &gt;= 0), takže nemá atraktor; flam3 ho kreslí jen tak, že zahazuje body, které utíkají</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: more than %2 xforms (at most %2 maps are supported)</source>
        <translation type="vanished">plamen „%1“: více než %2 xforms (podporováno je nejvýše %2 zobrazení)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: &lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %2 to %3, got &apos;%4&apos;</source>
        <translation type="vanished">plamen „%1“: &lt;symmetry&gt; vyžaduje kind=&quot;k&quot;, celé číslo od %2 do %3, zadáno „%4“</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its maps do not contract, not even on average (the Lyapunov exponent of their products, %2, is not clearly negative: not below -0.001), so it may have no attractor; flam3 draws it only by discarding the points that escape</source>
        <translation>plamen „%1“: jeho zobrazení nejsou kontrahující ani v průměru (Ljapunovův exponent jejich součinů, %2, není zřetelně záporný: není pod -0.001), takže nemusí mít atraktor; flam3 jej kreslí jen tak, že zahazuje unikající body</translation>
    </message>
    <message>
        <source>a flam3 flame</source>
        <translation>plamen flam3</translation>
    </message>
    <message>
        <source>%1 is an IFS of space: a flam3 flame holds maps of the plane (export it as a Fractint .ifs entry)</source>
        <translation>%1 je IFS prostoru: plamen flam3 obsahuje zobrazení roviny (exportujte jej jako položku Fractint .ifs)</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos rows let no xform follow another</source>
        <translation>plamen &apos;%1&apos;: jeho řádky xaos nedovolují, aby po kterékoli xform následovala jiná</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos rows make %2 arcs between its xforms, more than the %3 a controlled IFS may have</source>
        <translation>plamen &apos;%1&apos;: jeho řádky xaos vytvářejí mezi jeho xform %2 hran, více než %3, které smí mít řízený IFS</translation>
    </message>
    <message>
        <source>%1: flame &apos;%2&apos; not imported: %3</source>
        <translation>%1: plamen „%2“ nebyl importován: %3</translation>
    </message>
</context>
<context>
    <name>awb::FlameFile</name>
    <message>
        <source>the XML is malformed: %1</source>
        <translation>XML je chybně utvořené: %1</translation>
    </message>
    <message>
        <source>%1: the file holds no &lt;flame&gt; element</source>
        <translation>%1: soubor neobsahuje žádný prvek &lt;flame&gt;</translation>
    </message>
    <message>
        <source>%1, line %2, column %3: </source>
        <translation>%1, řádek %2, sloupec %3: </translation>
    </message>
    <message>
        <source>flame %1</source>
        <translation>plamen %1</translation>
    </message>
    <message>
        <source>a second &lt;finalxform&gt; (flam3 allows one)</source>
        <translation>druhý &lt;finalxform&gt; (flam3 povoluje jen jeden)</translation>
    </message>
    <message>
        <source>more than %1 xforms</source>
        <translation>více než %1 xformů</translation>
    </message>
    <message>
        <source>final xform</source>
        <translation>závěrečný xform</translation>
    </message>
    <message>
        <source>xform %1</source>
        <translation>xform %1</translation>
    </message>
    <message>
        <source>element &lt;%1&gt; ignored</source>
        <translation>prvek &lt;%1&gt; ignorován</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2</source>
        <translation>plamen „%1“: %2</translation>
    </message>
    <message>
        <source>xform %1: its xaos row has %2 entries for %3 xforms; the extra ones are ignored, as flam3 does</source>
        <translation>xform %1: jeho řádek xaos má %2 položek pro %3 xformů; nadbytečné se ignorují, stejně jako ve flam3</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; is not a finite number</source>
        <translation>%1=&quot;%2&quot; není konečné číslo</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be %3 finite numbers</source>
        <translation>%1=&quot;%2&quot; musí být konečná čísla v počtu %3</translation>
    </message>
    <message>
        <source>size=&quot;%1&quot; must be two whole numbers from 1 to 32768</source>
        <translation>size=&quot;%1&quot; musí být dvě celá čísla od 1 do 32768</translation>
    </message>
    <message>
        <source>scale=&quot;%1&quot; must be positive</source>
        <translation>scale=&quot;%1&quot; musí být kladné</translation>
    </message>
    <message>
        <source>zoom=&quot;%1&quot; is beyond +-50 (a factor 2^zoom)</source>
        <translation>zoom=&quot;%1&quot; je mimo rozsah +-50 (faktor 2^zoom)</translation>
    </message>
    <message>
        <source>quality=&quot;%1&quot; must be positive</source>
        <translation>quality=&quot;%1&quot; musí být kladné</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be a whole number from 1 to 64</source>
        <translation>%1=&quot;%2&quot; musí být celé číslo od 1 do 64</translation>
    </message>
    <message>
        <source>attributes not kept: %1</source>
        <translation>nezachované atributy: %1</translation>
    </message>
    <message>
        <source>weight=&quot;%1&quot; is negative</source>
        <translation>weight=&quot;%1&quot; je záporné</translation>
    </message>
    <message>
        <source>color=&quot;%1&quot; must be one or two finite numbers</source>
        <translation>color=&quot;%1&quot; musí být jedno nebo dvě konečná čísla</translation>
    </message>
    <message>
        <source>chaos=&quot;%1&quot; must be at most %2 finite numbers</source>
        <translation>chaos=&quot;%1&quot; musí být konečná čísla, nejvýše %2</translation>
    </message>
    <message>
        <source>chaos=&quot;%1&quot; has a negative entry</source>
        <translation>chaos=&quot;%1&quot; obsahuje zápornou položku</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be 6 finite numbers</source>
        <translation>%1=&quot;%2&quot; musí být 6 konečných čísel</translation>
    </message>
    <message>
        <source>var1=&quot;%1&quot; names no variation</source>
        <translation>var1=&quot;%1&quot; neoznačuje žádnou variaci</translation>
    </message>
    <message>
        <source>var=&quot;...&quot; must be %1 finite numbers, one per variation</source>
        <translation>var=&quot;...&quot; musí být konečná čísla v počtu %1, jedno pro každou variaci</translation>
    </message>
    <message>
        <source>: a final xform has no weight; weight=&quot;%1&quot; ignored</source>
        <translation>: závěrečný xform nemá váhu; weight=&quot;%1&quot; ignorováno</translation>
    </message>
    <message>
        <source>: no weight given; taken as 0, as flam3 does (the xform is never chosen)</source>
        <translation>: váha neuvedena; bere se 0, stejně jako ve flam3 (xform se nikdy nevybere)</translation>
    </message>
    <message>
        <source>: no variation given: as in flam3, every point goes to post(0)</source>
        <translation>: variace neuvedena: stejně jako ve flam3 jde každý bod na post(0)</translation>
    </message>
    <message>
        <source>: attributes flam3 does not draw, ignored: %1</source>
        <translation>: atributy, které flam3 nekreslí, ignorovány: %1</translation>
    </message>
    <message>
        <source>: animation attributes not kept: %1</source>
        <translation>: nezachované atributy animace: %1</translation>
    </message>
    <message>
        <source>: element &lt;%1&gt; ignored (animation)</source>
        <translation>: prvek &lt;%1&gt; ignorován (animace)</translation>
    </message>
    <message>
        <source>a &lt;color&gt; needs index=&quot;0..255&quot; and rgb=&quot;r g b&quot;</source>
        <translation>&lt;color&gt; vyžaduje index=&quot;0..255&quot; a rgb=&quot;r g b&quot;</translation>
    </message>
    <message>
        <source>a palette of flam3&apos;s palette file (index0) is not kept</source>
        <translation>paleta ze souboru palet flam3 (index0) se nezachovává</translation>
    </message>
    <message>
        <source>the palette&apos;s hex digits are not at most 256 colours of %1 digits</source>
        <translation>šestnáctkové číslice palety netvoří nejvýše 256 barev po %1 číslicích</translation>
    </message>
    <message>
        <source>palette entry %1 is not hexadecimal</source>
        <translation>položka palety %1 není šestnáctková</translation>
    </message>
    <message>
        <source>&lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %1 to %2</source>
        <translation type="vanished">&lt;symmetry&gt; vyžaduje kind=&quot;k&quot;, celé číslo od %1 do %2</translation>
    </message>
    <message>
        <source>&lt;symmetry kind=&quot;%1&quot;&gt; makes more than %2 xforms</source>
        <translation>&lt;symmetry kind=&quot;%1&quot;&gt; vytváří více než %2 xformů</translation>
    </message>
    <message>
        <source>&lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %1 to %2, got &apos;%3&apos;</source>
        <translation>&lt;symmetry&gt; vyžaduje kind=&quot;k&quot;, celé číslo od %1 do %2, zadáno „%3“</translation>
    </message>
    <message>
        <source>passes=&quot;%1&quot; must be a whole number from 1 to %2</source>
        <translation>passes=&quot;%1&quot; musí být celé číslo od 1 do %2</translation>
    </message>
    <message>
        <source>%1 is larger than 16 MB</source>
        <translation>%1 je větší než 16 MB</translation>
    </message>
    <message>
        <source>%1 cannot be read</source>
        <translation>%1 nelze přečíst</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 has no palette %2</source>
        <translation>%1 nemá paletu %2</translation>
    </message>
    <message>
        <source>its entry %1 has %2 hex digits, not 256 x 8</source>
        <translation>jeho položka %1 má %2 šestnáctkových číslic, ne 256 x 8</translation>
    </message>
    <message>
        <source>its entry %1 is not hexadecimal</source>
        <translation>jeho položka %1 není šestnáctková</translation>
    </message>
    <message>
        <source>palette %1 of flam3&apos;s palette file is not kept: %2</source>
        <translation>paleta %1 ze souboru palet flam3 se nezachovává: %2</translation>
    </message>
</context>
<context>
    <name>awb::FlameItem</name>
    <message>
        <source>expected 6 numbers in flam3&apos;s order [a, d, b, e, c, f]: x&apos; = a x + b y + c, y&apos; = d x + e y + f</source>
        <translation>očekáváno 6 čísel v pořadí flam3 [a, d, b, e, c, f]: x&apos; = a x + b y + c, y&apos; = d x + e y + f</translation>
    </message>
    <message>
        <source>expected a non-empty array of xforms</source>
        <translation>očekáváno neprázdné pole xformů</translation>
    </message>
    <message>
        <source>%1 xforms: at most %2 are drawn</source>
        <translation>počet xformů: %1; kreslí se nejvýše %2</translation>
    </message>
    <message>
        <source>expected 1536 hexadecimal digits (256 colours rrggbb), got %1</source>
        <translation>očekáváno 1536 šestnáctkových číslic (256 barev rrggbb), obdrženo %1</translation>
    </message>
    <message>
        <source>colour %1 is not hexadecimal</source>
        <translation>barva %1 není šestnáctková</translation>
    </message>
    <message>
        <source>expected 256 colours: a string of hexadecimal rrggbb, or [[r, g, b], ...] from 0 to 255</source>
        <translation type="vanished">očekáváno 256 barev: řetězec šestnáctkových rrggbb, nebo [[r, g, b], ...] od 0 do 255</translation>
    </message>
    <message>
        <source>expected [r, g, b]</source>
        <translation>očekáváno [r, g, b]</translation>
    </message>
    <message>
        <source>a channel must be from 0 to 255</source>
        <translation type="vanished">kanál musí být od 0 do 255</translation>
    </message>
    <message>
        <source>expected an xform {&quot;coefs&quot;: [...], &quot;variations&quot;: {...}, &quot;weight&quot;: w, ...}</source>
        <translation>očekáván xform {&quot;coefs&quot;: [...], &quot;variations&quot;: {...}, &quot;weight&quot;: w, ...}</translation>
    </message>
    <message>
        <source>a weight must not be negative</source>
        <translation>váha nesmí být záporná</translation>
    </message>
    <message>
        <source>flam3 has no variation of this name</source>
        <translation>flam3 nemá variaci tohoto jména</translation>
    </message>
    <message>
        <source>no variation of flam3 has this parameter</source>
        <translation>žádná variace flam3 nemá tento parametr</translation>
    </message>
    <message>
        <source>a xaos entry must not be negative</source>
        <translation>položka xaos nesmí být záporná</translation>
    </message>
    <message>
        <source>not a field of an xform (coefs, post, variations, parameters, weight, color, color_speed, opacity, animate, chaos, name)</source>
        <translation>není pole xformu (coefs, post, variations, parameters, weight, color, color_speed, opacity, animate, chaos, name)</translation>
    </message>
    <message>
        <source>Flame</source>
        <translation>Plamen</translation>
    </message>
    <message>
        <source>the scale (pixels per unit) must be positive</source>
        <translation>měřítko (pixely na jednotku) musí být kladné</translation>
    </message>
    <message>
        <source>a flame is drawn by random iteration only (its maps are not affine): choose random iteration</source>
        <translation>plamen se kreslí pouze náhodnou iterací (jeho zobrazení nejsou afinní): zvolte náhodnou iteraci</translation>
    </message>
    <message>
        <source>a flame&apos;s xforms carry their own weights (&quot;xforms&quot;): leave the algorithm&apos;s probabilities empty</source>
        <translation>xformy plamene nesou vlastní váhy (&quot;xforms&quot;): ponechte pravděpodobnosti algoritmu prázdné</translation>
    </message>
    <message>
        <source>a flame has no subdivision matrices: its maps are not affine</source>
        <translation>plamen nemá subdivizní matice: jeho zobrazení nejsou afinní</translation>
    </message>
    <message>
        <source>a fractal flame, drawn by its own chaos game as flam3 draws it; the spectra are those of the xforms&apos; affine (pre) maps, y up</source>
        <translation>fraktální plamen, kreslený vlastní hrou chaosu tak, jak jej kreslí flam3; spektra jsou spektry afinních (pre) zobrazení xformů, y nahoru</translation>
    </message>
    <message>
        <source>Change flame of %1</source>
        <translation>Změnit plamen %1</translation>
    </message>
    <message>
        <source>Xforms</source>
        <translation>Xformy</translation>
    </message>
    <message>
        <source>flam3&apos;s xforms: {&quot;coefs&quot;: [a, d, b, e, c, f], &quot;variations&quot;: {&quot;linear&quot;: 1, ...}, &quot;weight&quot;: w, &quot;color&quot;: c, ...} each</source>
        <translation>xformy flam3: každý {&quot;coefs&quot;: [a, d, b, e, c, f], &quot;variations&quot;: {&quot;linear&quot;: 1, ...}, &quot;weight&quot;: w, &quot;color&quot;: c, ...}</translation>
    </message>
    <message>
        <source>Final xform</source>
        <translation>Závěrečná xform</translation>
    </message>
    <message>
        <source>Drawn on every point without moving the orbit; null: none</source>
        <translation>Použije se na každý kreslený bod, aniž by posunul orbitu; null: žádný</translation>
    </message>
    <message>
        <source>Palette</source>
        <translation>Paleta</translation>
    </message>
    <message>
        <source>256 colours, indexed by the colour coordinate</source>
        <translation>256 barev, indexovaných barevnou souřadnicí</translation>
    </message>
    <message>
        <source>Centre x</source>
        <translation>Střed x</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Centre y</source>
        <translation>Střed y</translation>
    </message>
    <message>
        <source>flam3&apos;s: y grows down the picture</source>
        <translation>podle flam3: y roste směrem dolů obrázku</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>Měřítko</translation>
    </message>
    <message>
        <source>Pixels per unit (times 2^zoom)</source>
        <translation>Pixely na jednotku (krát 2^zoom)</translation>
    </message>
    <message>
        <source>Rotation (degrees)</source>
        <translation>Otočení (stupně)</translation>
    </message>
    <message>
        <source>Zoom</source>
        <translation>Přiblížení</translation>
    </message>
    <message>
        <source>Width (pixels)</source>
        <translation>Šířka (pixely)</translation>
    </message>
    <message>
        <source>Height (pixels)</source>
        <translation>Výška (pixely)</translation>
    </message>
    <message>
        <source>Quality (samples per pixel)</source>
        <translation>Kvalita (vzorky na pixel)</translation>
    </message>
    <message>
        <source>Tone</source>
        <translation>Tónování</translation>
    </message>
    <message>
        <source>Brightness</source>
        <translation>Jas</translation>
    </message>
    <message>
        <source>Gamma</source>
        <translation>Gama</translation>
    </message>
    <message>
        <source>Gamma threshold</source>
        <translation>Práh gamy</translation>
    </message>
    <message>
        <source>Vibrancy</source>
        <translation>Sytost</translation>
    </message>
    <message>
        <source>Highlight power</source>
        <translation>Síla světel</translation>
    </message>
    <message>
        <source>flam3&apos;s: -1 leaves the highlights as they are</source>
        <translation>podle flam3: -1 ponechá světla beze změny</translation>
    </message>
    <message>
        <source>expected [r, g, b] from 0 to 1</source>
        <translation>očekáváno [r, g, b] od 0 do 1</translation>
    </message>
    <message>
        <source>Background</source>
        <translation>Pozadí</translation>
    </message>
    <message>
        <source>[r, g, b] from 0 to 1</source>
        <translation>[r, g, b] od 0 do 1</translation>
    </message>
    <message>
        <source>Supersample</source>
        <translation>Supervzorkování</translation>
    </message>
    <message>
        <source>Filter radius (pixels)</source>
        <translation>Poloměr filtru (pixely)</translation>
    </message>
    <message>
        <source>Estimator radius</source>
        <translation>Poloměr estimátoru</translation>
    </message>
    <message>
        <source>Estimator minimum</source>
        <translation>Minimum estimátoru</translation>
    </message>
    <message>
        <source>Estimator curve</source>
        <translation>Křivka estimátoru</translation>
    </message>
    <message>
        <source>Fractal flame</source>
        <translation>Fraktální plamen</translation>
    </message>
    <message>
        <source>expected 256 colours: a string of hexadecimal rrggbb, or [[r, g, b], ...] from 0 to 1</source>
        <translation>očekáváno 256 barev: řetězec šestnáctkových rrggbb, nebo [[r, g, b], ...] od 0 do 1</translation>
    </message>
    <message>
        <source>a channel must be from 0 to 1</source>
        <translation>kanál musí být od 0 do 1</translation>
    </message>
    <message>
        <source>Gaussian</source>
        <translation>Gaussův</translation>
    </message>
    <message>
        <source>Hermite</source>
        <translation>Hermitův</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Obdélníkový</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation>Trojúhelníkový</translation>
    </message>
    <message>
        <source>Bell</source>
        <translation>Zvonový</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-spline</translation>
    </message>
    <message>
        <source>Lanczos 3 (flam3 draws Mitchell)</source>
        <translation>Lanczos 3 (flam3 kreslí Mitchell)</translation>
    </message>
    <message>
        <source>Lanczos 2 (flam3 draws Blackman)</source>
        <translation>Lanczos 2 (flam3 kreslí Blackman)</translation>
    </message>
    <message>
        <source>Mitchell (flam3 draws Catmull-Rom)</source>
        <translation>Mitchell (flam3 kreslí Catmull-Rom)</translation>
    </message>
    <message>
        <source>Blackman (flam3 draws Hanning)</source>
        <translation>Blackman (flam3 kreslí Hanning)</translation>
    </message>
    <message>
        <source>Catmull-Rom (flam3 draws Hamming)</source>
        <translation>Catmull-Rom (flam3 kreslí Hamming)</translation>
    </message>
    <message>
        <source>Hamming (flam3 draws Lanczos 3)</source>
        <translation>Hamming (flam3 kreslí Lanczos 3)</translation>
    </message>
    <message>
        <source>Hanning (flam3 draws Lanczos 2)</source>
        <translation>Hanning (flam3 kreslí Lanczos 2)</translation>
    </message>
    <message>
        <source>Quadratic</source>
        <translation>Kvadratický</translation>
    </message>
    <message>
        <source>Filter shape</source>
        <translation>Tvar filtru</translation>
    </message>
    <message>
        <source>flam3&apos;s filter_shape; from Lanczos 3 on, flam3 3.1.1 draws another shape than the name says, and so do we</source>
        <translation>filter_shape programu flam3; od Lanczos 3 dál kreslí flam3 3.1.1 jiný tvar, než říká název, a my také</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Skokový</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineární</translation>
    </message>
    <message>
        <source>Palette mode</source>
        <translation>Režim palety</translation>
    </message>
    <message>
        <source>flam3&apos;s palette_mode: a hit takes the palette entry at its colour coordinate (step) or between the two entries around it (linear)</source>
        <translation>palette_mode programu flam3: zásah dostane položku palety na své barevné souřadnici (skokově) nebo barvu mezi dvěma okolními položkami (lineárně)</translation>
    </message>
    <message>
        <source>Passes</source>
        <translation>Průchody</translation>
    </message>
    <message>
        <source>flam3&apos;s passes: the samples drawn in that many histograms, each log-scaled and density-estimated apart, then summed (a little smoother than one)</source>
        <translation>passes programu flam3: vzorky se kreslí do tolika histogramů, každý se zvlášť logaritmicky škáluje a odhaduje se jeho hustota, pak se sečtou (o něco hladší než jeden)</translation>
    </message>
</context>
<context>
    <name>awb::FlameXformEditor</name>
    <message>
        <source>The xform to edit; its pre map is its triangle in the attractor view (drag a corner) and in the point table below</source>
        <translation>Xform k úpravě; její počáteční zobrazení je její trojúhelník v pohledu na atraktor (táhněte roh) a v tabulce bodů níže</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Přidat</translation>
    </message>
    <message>
        <source>A new xform (linear, weight 1) after the others</source>
        <translation>Nová xform (lineární, váha 1) za ostatními</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Zdvojit</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Smazat</translation>
    </message>
    <message>
        <source>Weight:</source>
        <translation>Váha:</translation>
    </message>
    <message>
        <source>Colour:</source>
        <translation>Barva:</translation>
    </message>
    <message>
        <source>Colour speed:</source>
        <translation>Rychlost barvy:</translation>
    </message>
    <message>
        <source>Opacity:</source>
        <translation>Neprůhlednost:</translation>
    </message>
    <message>
        <source>Variation</source>
        <translation>Variace</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Váha</translation>
    </message>
    <message>
        <source>The xform&apos;s variations; a weight of 0 removes one</source>
        <translation>Variace xform; váha 0 jednu odebere</translation>
    </message>
    <message>
        <source>Add a variation…</source>
        <translation>Přidat variaci…</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parametr</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Hodnota</translation>
    </message>
    <message>
        <source>The parameters of the xform&apos;s variations</source>
        <translation>Parametry variací xform</translation>
    </message>
    <message>
        <source>A flame needs at least one xform.</source>
        <translation>Plamen potřebuje alespoň jednu xform.</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation type="vanished">Barva</translation>
    </message>
    <message>
        <source>Colour speed</source>
        <translation type="vanished">Rychlost barvy</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation type="vanished">Neprůhlednost</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="vanished">%1: %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: &apos;%2&apos; není číslo</translation>
    </message>
    <message>
        <source>Xform %1</source>
        <translation>Xform %1</translation>
    </message>
    <message>
        <source>Xform %1: %2</source>
        <translation>Xform %1: %2</translation>
    </message>
    <message>
        <source>Final xform</source>
        <translation>Závěrečná xform</translation>
    </message>
</context>
<context>
    <name>awb::FractalItem</name>
    <message>
        <source>expected an array of %1 numbers</source>
        <translation>očekáváno pole čísel o délce %1</translation>
    </message>
    <message>
        <source>missing (the custom form needs its maps)</source>
        <translation>chybí (vlastní tvar potřebuje svá zobrazení)</translation>
    </message>
    <message>
        <source>expected a non-empty array of maps {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</source>
        <translation>očekáváno neprázdné pole zobrazení {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</translation>
    </message>
    <message>
        <source>expected an object with &quot;A&quot; and &quot;b&quot;</source>
        <translation>očekáván objekt s &quot;A&quot; a &quot;b&quot;</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>chybí</translation>
    </message>
    <message>
        <source>expected a 2 x 2 matrix [[a11, a12], [a21, a22]]</source>
        <translation type="vanished">očekávána matice 2 x 2 [[a11, a12], [a21, a22]]</translation>
    </message>
    <message>
        <source>the custom form needs at least one map</source>
        <translation>vlastní tvar vyžaduje alespoň jedno zobrazení</translation>
    </message>
    <message>
        <source>map %1 is not a map of the plane</source>
        <translation type="vanished">zobrazení %1 není zobrazení roviny</translation>
    </message>
    <message>
        <source>map %1 has a non-finite entry</source>
        <translation>zobrazení %1 má nekonečný prvek</translation>
    </message>
    <message>
        <source>a reference point is not finite</source>
        <translation>referenční bod není konečný</translation>
    </message>
    <message>
        <source>need at least 3 reference points (000 §4), got %1</source>
        <translation>jsou potřeba alespoň 3 referenční body (000 §4), zadáno %1</translation>
    </message>
    <message>
        <source>Fractal</source>
        <translation>Fraktál</translation>
    </message>
    <message>
        <source>Change fractal of %1</source>
        <translation>Změnit fraktál položky %1</translation>
    </message>
    <message>
        <source>the %1 reference points and the %2 control points must be equally many</source>
        <translation>počet referenčních bodů (%1) a řídicích bodů (%2) musí být stejný</translation>
    </message>
    <message>
        <source>the reference points are ill-conditioned: S_i R differs from f_i(R) by up to %1</source>
        <translation>referenční body jsou špatně podmíněné: S_i R se od f_i(R) liší až o %1</translation>
    </message>
    <message>
        <source>Koch curve (000 §4.1)</source>
        <translation>Kochova křivka (000 §4.1)</translation>
    </message>
    <message>
        <source>Sierpinski triangle (000 §4.2)</source>
        <translation>Sierpinského trojúhelník (000 §4.2)</translation>
    </message>
    <message>
        <source>Own maps</source>
        <translation>Vlastní zobrazení</translation>
    </message>
    <message>
        <source>The presets use the paper&apos;s printed matrices S_i</source>
        <translation>Předvolby používají matice S_i vytištěné v článku</translation>
    </message>
    <message>
        <source>Affine weights</source>
        <translation>Afinní váhy</translation>
    </message>
    <message>
        <source>Nearest control points</source>
        <translation>Nejbližší řídicí body</translation>
    </message>
    <message>
        <source>Least norm (all points)</source>
        <translation>Nejmenší norma (všechny body)</translation>
    </message>
    <message>
        <source>How f_i(P_j) is written as an affine combination of the control points (000 eq. (5)): nearest points keep edits local, least norm lets every point move the whole fractal</source>
        <translation>Jak se f_i(P_j) zapíše jako afinní kombinace řídicích bodů (000 eq. (5)): nejbližší body udrží úpravy lokální, nejmenší norma dovolí každému bodu pohnout celým fraktálem</translation>
    </message>
    <message>
        <source>Fractal with control points</source>
        <translation>Fraktál s řídicími body</translation>
    </message>
    <message>
        <source>expected a 2 x 2 matrix [[a11, a12], [a21, a22]] or a 3 x 3 one</source>
        <translation>očekávána matice 2 x 2 [[a11, a12], [a21, a22]] nebo 3 x 3</translation>
    </message>
    <message>
        <source>expected a %1 x %1 matrix, as the first map</source>
        <translation>očekávána matice %1 x %1, stejně jako u prvního zobrazení</translation>
    </message>
    <message>
        <source>map %1 is not a map of the plane or of space like the first</source>
        <translation>zobrazení %1 není zobrazení roviny nebo prostoru stejné dimenze jako první</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>Zobrazení</translation>
    </message>
    <message>
        <source>x ↦ x A + b: {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]} each, or 3 x 3 and 3 numbers in space</source>
        <translation>x ↦ x A + b: každé jako {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}, v prostoru matice 3 x 3 a 3 čísla</translation>
    </message>
    <message>
        <source>Reference points</source>
        <translation>Referenční body</translation>
    </message>
    <message>
        <source>The points the S_i are built for (S_i R = f_i(R)); none: the control points themselves</source>
        <translation>Body, pro které se S_i sestavují (S_i R = f_i(R)); žádné: samotné řídicí body</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Řídicí body</translation>
    </message>
    <message>
        <source>%1 maps: at most %2 maps are supported</source>
        <translation>%1 zobrazení: podporováno je nejvýše %2 zobrazení</translation>
    </message>
</context>
<context>
    <name>awb::IfsExchange</name>
    <message>
        <source>%1, line %2: entry %3: %4 (%5)</source>
        <translation>%1, řádek %2: záznam %3: %4 (%5)</translation>
    </message>
    <message>
        <source>%1, line %2: %3</source>
        <translation>%1, řádek %2: %3</translation>
    </message>
    <message>
        <source>%1: the file is larger than %2 MB</source>
        <translation>%1: soubor je větší než %2 MB</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>nelze číst %1: %2</translation>
    </message>
    <message>
        <source>%1 cannot be computed: %2</source>
        <translation>%1 nelze vypočítat: %2</translation>
    </message>
    <message>
        <source>the IFS of %1 acts in a space of dimension %2 that is drawn through a projection (000 §2): a Fractint entry holds maps of the plane or of space only</source>
        <translation type="vanished">IFS položky %1 působí v prostoru dimenze %2, který se kreslí pomocí projekce (000 §2): záznam formátu Fractint obsahuje jen zobrazení roviny nebo prostoru</translation>
    </message>
    <message>
        <source>the IFS of %1 acts in a space of dimension %2 that is drawn through a projection (000 §2), and its maps do not act on the drawn coordinates alone: %3 holds maps of the plane or of space only</source>
        <translation>IFS položky %1 působí v prostoru dimenze %2, který se kreslí projekcí (000 §2), a jeho zobrazení nepůsobí jen na kreslené souřadnice: %3 obsahuje pouze zobrazení roviny nebo prostoru</translation>
    </message>
    <message>
        <source>%1 is a fractal flame: its xforms are not affine maps, and %2 holds affine maps only (export it as a flam3 flame)</source>
        <translation>%1 je fraktální plamen: jeho xformy nejsou afinní zobrazení a %2 obsahuje pouze afinní zobrazení (exportujte jej jako plamen flam3)</translation>
    </message>
</context>
<context>
    <name>awb::InsertControlPointCommand</name>
    <message>
        <source>Add a control point to %1</source>
        <translation>Přidat řídicí bod do položky %1</translation>
    </message>
</context>
<context>
    <name>awb::InsertItemCommand</name>
    <message>
        <source>Add %1</source>
        <translation>Přidat %1</translation>
    </message>
</context>
<context>
    <name>awb::Item</name>
    <message>
        <source>Rename</source>
        <translation>Přejmenovat</translation>
    </message>
    <message>
        <source>Change style of %1</source>
        <translation>Změnit styl položky %1</translation>
    </message>
    <message>
        <source>Edit animation of %1</source>
        <translation>Upravit animaci položky %1</translation>
    </message>
    <message>
        <source>the name cannot be empty</source>
        <translation>název nemůže být prázdný</translation>
    </message>
    <message>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 nemá parametr „%2“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid value for %2</source>
        <translation>„%1“ není platná hodnota pro %2</translation>
    </message>
    <message>
        <source>circular reference</source>
        <translation>cyklický odkaz</translation>
    </message>
    <message>
        <source>there is not enough memory to compute it</source>
        <translation>k výpočtu není dostatek paměti</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>By map</source>
        <translation>Podle zobrazení</translation>
    </message>
    <message>
        <source>By address prefix</source>
        <translation>Podle prefixu adresy</translation>
    </message>
    <message>
        <source>Single colour</source>
        <translation>Jedna barva</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Barva</translation>
    </message>
    <message>
        <source>Style</source>
        <translation>Styl</translation>
    </message>
    <message>
        <source>The attractor&apos;s colours: by the map that made each point, by the first symbols of its address, or one colour</source>
        <translation>Barvy atraktoru: podle zobrazení, které daný bod vytvořilo, podle prvních symbolů jeho adresy, nebo jedna barva</translation>
    </message>
    <message>
        <source>Prefix length</source>
        <translation>Délka prefixu</translation>
    </message>
    <message>
        <source>Colour by address: how many of its first symbols pick the colour</source>
        <translation>Barvení podle adresy: kolik prvních symbolů adresy určuje barvu</translation>
    </message>
    <message>
        <source>Point size</source>
        <translation>Velikost bodů</translation>
    </message>
    <message>
        <source>Points of the attractor, in pixels</source>
        <translation>Velikost bodů atraktoru v pixelech</translation>
    </message>
    <message>
        <source>expected an array of &quot;#rrggbb&quot; strings</source>
        <translation>očekáváno pole řetězců &quot;#rrggbb&quot;</translation>
    </message>
    <message>
        <source>expected a string &quot;#rrggbb&quot;</source>
        <translation>očekáván řetězec &quot;#rrggbb&quot;</translation>
    </message>
    <message>
        <source>Palette</source>
        <translation>Paleta</translation>
    </message>
    <message>
        <source>Own colours, one per map or address prefix (&quot;#rrggbb&quot;); none: the views&apos; palette</source>
        <translation>Vlastní barvy, jedna pro každé zobrazení nebo prefix adresy (&quot;#rrggbb&quot;); žádné: paleta pohledů</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatický</translation>
    </message>
    <message>
        <source>Hits</source>
        <translation>Zásahy</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>Hustota</translation>
    </message>
    <message>
        <source>Tone</source>
        <translation>Tónování</translation>
    </message>
    <message>
        <source>Hits: every pixel the attractor reaches (the papers&apos; look); density: the invariant measure by log density; automatic: hits for deterministic, density for random iteration</source>
        <translation>Zásahy: každý pixel, kam atraktor dosáhne (vzhled jako v článcích); hustota: invariantní míra jako logaritmická hustota; automatický: zásahy pro deterministickou, hustota pro náhodnou iteraci</translation>
    </message>
    <message>
        <source>Gamma</source>
        <translation>Gama</translation>
    </message>
    <message>
        <source>Gamma of the density tone</source>
        <translation>Gama tónu hustoty</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animace</translation>
    </message>
    <message>
        <source>%1 is outside the range from %2 to %3</source>
        <translation>%1 je mimo rozsah od %2 do %3</translation>
    </message>
    <message>
        <source>%1 must be a finite number</source>
        <translation>%1 musí být konečné číslo</translation>
    </message>
    <message>
        <source>%1 must be at least %2 and at most %3, not %4</source>
        <translation>%1 musí být nejméně %2 a nejvýše %3, ne %4</translation>
    </message>
    <message>
        <source>%1 must be at least %2, not %3</source>
        <translation>%1 musí být nejméně %2, ne %3</translation>
    </message>
    <message>
        <source>%1 must be at most %2, not %3</source>
        <translation>%1 musí být nejvýše %2, ne %3</translation>
    </message>
    <message>
        <source>expected [re, im] or a number</source>
        <translation>očekáváno [re, im] nebo číslo</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not %3</source>
        <translation>%1: „%2“ není %3</translation>
    </message>
    <message>
        <source>a JSON value (%1)</source>
        <translation>hodnota JSON (%1)</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>číslo</translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation>celé číslo</translation>
    </message>
    <message>
        <source>one of %1 (or its number from 0)</source>
        <translation>jedna z hodnot %1 (nebo její číslo od 0)</translation>
    </message>
    <message>
        <source>a complex number (&quot;0.5,0.3&quot; or &quot;0.5+0.3i&quot;)</source>
        <translation>komplexní číslo (&quot;0.5,0.3&quot; nebo &quot;0.5+0.3i&quot;)</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true nebo false</translation>
    </message>
    <message>
        <source>an item&apos;s type cannot change (%1 to %2): add a new item</source>
        <translation>typ položky nelze změnit (%1 na %2): přidejte novou položku</translation>
    </message>
    <message>
        <source>children are items of their own: add, remove or update them</source>
        <translation>podřízené položky jsou samostatné položky: přidávejte, odebírejte nebo aktualizujte je zvlášť</translation>
    </message>
    <message>
        <source>Update %1</source>
        <translation>Aktualizovat položku %1</translation>
    </message>
    <message>
        <source>%1 is shown, not edited</source>
        <translation>%1 se jen zobrazuje, nelze upravit</translation>
    </message>
    <message>
        <source>Change %1 of %2</source>
        <translation>Změnit %1 položky %2</translation>
    </message>
</context>
<context>
    <name>awb::ItemAddress</name>
    <message>
        <source>t: the B-spline&apos;s knot parameter scaled to [0, 1] (the address in base 2)</source>
        <translation>t: uzlový parametr B-spline přeškálovaný na [0, 1] (adresa ve dvojkové soustavě)</translation>
    </message>
    <message>
        <source>t: the knot parameter scaled to [0, 1] (the address in base 2)</source>
        <translation>t: uzlový parametr přeškálovaný na [0, 1] (adresa ve dvojkové soustavě)</translation>
    </message>
    <message>
        <source>t: the Bernstein parameter (the address in base 2)</source>
        <translation>t: Bernsteinův parametr (adresa ve dvojkové soustavě)</translation>
    </message>
    <message>
        <source>t: the Bernstein parameter (pieces [0, t], [t, 1] of the split)</source>
        <translation>t: Bernsteinův parametr (části [0, t], [t, 1] dělení)</translation>
    </message>
    <message>
        <source>t: the scheme&apos;s own parameter, the address read in base %1</source>
        <translation>t: vlastní parametr schématu, adresa čtená v soustavě o základu %1</translation>
    </message>
    <message>
        <source>this item is drawn by an automaton: its words are not addresses of one IFS</source>
        <translation>tato položka je kreslena automatem: její slova nejsou adresami jednoho IFS</translation>
    </message>
    <message>
        <source>a parameter interval is [t0, t1] with two numbers, e.g. [0.25, 0.5]</source>
        <translation>interval parametru je [t0, t1] se dvěma čísly, např. [0.25, 0.5]</translation>
    </message>
    <message>
        <source>the parameter interval [%1, %2] must satisfy 0 &lt;= t0 &lt; t1 &lt;= 1</source>
        <translation>interval parametru [%1, %2] musí splňovat 0 &lt;= t0 &lt; t1 &lt;= 1</translation>
    </message>
</context>
<context>
    <name>awb::ItemAnalysis</name>
    <message>
        <source>not measured: the flame&apos;s maps are not their affine parts, whose attractor the analysis would count</source>
        <translation>neměřeno: zobrazení plamene nejsou jejich afinní části, jejichž atraktor by analýza počítala</translation>
    </message>
</context>
<context>
    <name>awb::ItemController</name>
    <message>
        <source>%1 shows nothing: %2</source>
        <translation>%1 nic nezobrazuje: %2</translation>
    </message>
    <message>
        <source>%1 has no attractor to draw.</source>
        <translation>%1 nemá žádný atraktor ke kreslení.</translation>
    </message>
    <message>
        <source>%1 cannot be drawn: %2</source>
        <translation>%1 nelze vykreslit: %2</translation>
    </message>
    <message>
        <source>Regularity: only for subdivision curves</source>
        <translation>Regularita: jen pro subdivizní křivky</translation>
    </message>
    <message>
        <source>Regularity: does not apply (%1)</source>
        <translation type="vanished">Regularita: nelze použít (%1)</translation>
    </message>
    <message>
        <source>complex de Casteljau parameter</source>
        <translation type="vanished">komplexní de Casteljauův parametr</translation>
    </message>
    <message>
        <source>the scheme&apos;s parameters are refused</source>
        <translation type="vanished">parametry schématu byly odmítnuty</translation>
    </message>
    <message>
        <source>Changing %1 (%2, %3) from %4 to %5 makes row %2 sum to %6, not 1: the rows of a subdivision matrix are affine combinations.

Take the difference %7 from the entry in column %8 (%9 → %10) so that the row sums to 1?</source>
        <translation>Změna %1 (%2, %3) z %4 na %5 způsobí, že součet řádku %2 bude %6, a ne 1: řádky subdivizní matice jsou afinní kombinace.

Odečíst rozdíl %7 od prvku ve sloupci %8 (%9 → %10), aby byl součet řádku 1?</translation>
    </message>
    <message>
        <source>%1 (%2, %3) = %4 was refused: %5</source>
        <translation>%1 (%2, %3) = %4 bylo odmítnuto: %5</translation>
    </message>
    <message>
        <source>Insert Point &amp;Before %1</source>
        <translation>Vložit bod &amp;před %1</translation>
    </message>
    <message>
        <source>Insert Point &amp;After %1</source>
        <translation>Vložit bod &amp;za %1</translation>
    </message>
    <message>
        <source>&amp;Delete Point %1</source>
        <translation>&amp;Odstranit bod %1</translation>
    </message>
    <message>
        <source>&amp;Insert Point Here</source>
        <translation>&amp;Vložit bod sem</translation>
    </message>
    <message>
        <source>&amp;Append Point Here</source>
        <translation>Přid&amp;at bod sem</translation>
    </message>
    <message>
        <source>&amp;Fit View</source>
        <translation>Přizpůsobit po&amp;hled</translation>
    </message>
    <message>
        <source>Fᵏ(X₀)</source>
        <translation>Fᵏ(X₀)</translation>
    </message>
    <message>
        <source>Fᵏ(X₀) to the %1</source>
        <translation>Fᵏ(X₀) k %1</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>vrchol %1</translation>
    </message>
    <message>
        <source>the centre of face %1</source>
        <translation>střed stěny %1</translation>
    </message>
    <message>
        <source>S at %1 (n = %2)</source>
        <translation>S (%1, n = %2)</translation>
    </message>
    <message>
        <source>The Vertex tab analyses the extraordinary vertices of a mesh surface (Item &gt; Add &gt; Mesh surface, File &gt; Import Mesh).</source>
        <translation>Karta Vrchol analyzuje mimořádné vrcholy plochy ze sítě (Položka &gt; Přidat &gt; Plocha ze sítě, Soubor &gt; Importovat síť).</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 položky %2</translation>
    </message>
    <message>
        <source>Eigenvalues at %1</source>
        <translation>Vlastní čísla (%1)</translation>
    </message>
    <message>
        <source>%1 cannot be removed: an IFS of own matrices needs at least two maps</source>
        <translation>%1 nelze odebrat: IFS z vlastních matic potřebuje alespoň dvě zobrazení</translation>
    </message>
    <message>
        <source>No map was added: %1</source>
        <translation>Zobrazení nebylo přidáno: %1</translation>
    </message>
    <message>
        <source>No map was removed: %1</source>
        <translation>Zobrazení nebylo odebráno: %1</translation>
    </message>
    <message>
        <source>Save Regularity Certificate</source>
        <translation>Uložit certifikát regularity</translation>
    </message>
    <message>
        <source>Regularity certificate (*.json)</source>
        <translation>Certifikát regularity (*.json)</translation>
    </message>
    <message>
        <source>No certificate: the regularity of the current curve is not computed yet.</source>
        <translation>Žádný certifikát: regularita aktuální křivky ještě není spočtena.</translation>
    </message>
    <message>
        <source>No certificate was saved: %1</source>
        <translation>Certifikát nebyl uložen: %1</translation>
    </message>
    <message>
        <source>Saved the regularity certificate to %1</source>
        <translation>Certifikát regularity uložen do %1</translation>
    </message>
</context>
<context>
    <name>awb::ItemFigure</name>
    <message>
        <source>the 16-bit density is written to PNG files, got &apos;%1&apos;</source>
        <translation>16bitová hustota se zapisuje do souborů PNG, zadáno „%1“</translation>
    </message>
    <message>
        <source>the raw density (.exr, 16-bit PNG) counts an attractor&apos;s points; this item&apos;s figure is a polygon</source>
        <translation>surová hustota (.exr, 16bitové PNG) počítá body atraktoru; obrazem této položky je polygon</translation>
    </message>
    <message>
        <source>the rendering was cancelled</source>
        <translation>vykreslování bylo zrušeno</translation>
    </message>
    <message>
        <source>item &apos;%1&apos;: %2</source>
        <translation>položka „%1“: %2</translation>
    </message>
    <message>
        <source>depth %1 makes %2 images; at most 4e9 are rendered</source>
        <translation>hloubka %1 dává %2 obrazů; vykresluje se nejvýše 4e9</translation>
    </message>
    <message>
        <source>the raw density (.exr, 16-bit PNG) is of attractors drawn in the plane; &apos;%1&apos; is drawn in space</source>
        <translation>surová hustota (.exr, 16bitové PNG) je pro atraktory kreslené v rovině; „%1“ se kreslí v prostoru</translation>
    </message>
    <message>
        <source>the view must be azimuth and elevation in degrees with |elevation| &lt;= 90, got %1, %2</source>
        <translation>pohled musí být azimut a elevace ve stupních s |elevace| &lt;= 90, zadáno %1, %2</translation>
    </message>
    <message>
        <source>%1 random points</source>
        <translation>%1 náhodných bodů</translation>
    </message>
    <message>
        <source>F^%1(X0)</source>
        <translation>F^%1(X0)</translation>
    </message>
    <message>
        <source>, maps %1 of %2</source>
        <translation>, zobrazení %1 z %2</translation>
    </message>
    <message>
        <source>%1: %2%3 — orthographic view from azimuth %4°, elevation %5°</source>
        <translation>%1: %2%3 — ortografický pohled z azimutu %4°, elevace %5°</translation>
    </message>
    <message>
        <source>%1: %2 random points</source>
        <translation>%1: %2 náhodných bodů</translation>
    </message>
    <message>
        <source>%1: F^%2(X0)</source>
        <translation>%1: F^%2(X0)</translation>
    </message>
    <message>
        <source>%1: polygon after %2 steps</source>
        <translation>%1: polygon po kroku %2</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is drawn by random iteration only (its maps are not affine): give --samples, not --depth</source>
        <translation>položka „%1“ se kreslí pouze náhodnou iterací (její zobrazení nejsou afinní): zadejte --samples, ne --depth</translation>
    </message>
    <message>
        <source>give --bounds: the item has no frame of its own</source>
        <translation>zadejte --bounds: položka nemá vlastní rámec</translation>
    </message>
    <message>
        <source>%1 samples; at most %2</source>
        <translation>%1 vzorků; nejvýše %2</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation type="vanished">nelze zapsat %1</translation>
    </message>
</context>
<context>
    <name>awb::JunctionSpec</name>
    <message>
        <source>the junction parameter %1 must be a finite number</source>
        <translation>parametr napojení %1 musí být konečné číslo</translation>
    </message>
    <message>
        <source>%1 = %2 is outside (%3, %4): %5</source>
        <translation>%1 = %2 leží mimo (%3, %4): %5</translation>
    </message>
</context>
<context>
    <name>awb::MainWindow</name>
    <message>
        <source>Attractor Workbench projects (*.awb);;All files (*)</source>
        <translation>Projekty Attractor Workbench (*.awb);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatické ukládání selhalo: %1</translation>
    </message>
    <message>
        <source>&lt;original&gt;</source>
        <translation>&lt;původní stav&gt;</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Cancel the analysis</source>
        <translation>Zrušit analýzu</translation>
    </message>
    <message>
        <source>Drawing %p%</source>
        <translation>Kreslení %p%</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Zastavit</translation>
    </message>
    <message>
        <source>Stop drawing the attractor (Esc); F5 draws it again</source>
        <translation>Zastavit kreslení atraktoru (Esc); klávesou F5 jej vykreslíte znovu</translation>
    </message>
    <message>
        <source>Drawing the attractor for the figure…</source>
        <translation>Kreslení atraktoru pro obrázek…</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>Obrázek</translation>
    </message>
    <message>
        <source>Drawing stopped; press F5 to draw again.</source>
        <translation>Kreslení zastaveno; klávesou F5 jej spustíte znovu.</translation>
    </message>
    <message>
        <source>Analysis %p%</source>
        <translation>Analýza %p%</translation>
    </message>
    <message>
        <source>Analysis cancelled.</source>
        <translation>Analýza zrušena.</translation>
    </message>
    <message>
        <source>Row sum</source>
        <translation>Součet řádku</translation>
    </message>
    <message>
        <source>Edit refused</source>
        <translation>Úprava odmítnuta</translation>
    </message>
    <message>
        <source>x = %1, y = %2</source>
        <translation>x = %1, y = %2</translation>
    </message>
    <message>
        <source>Drawing failed: %1</source>
        <translation>Kreslení selhalo: %1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nový</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Otevřít…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Uložit</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Uložit j&amp;ako…</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>&amp;Vrátit k uloženému</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Zavřít</translation>
    </message>
    <message>
        <source>&amp;Print…</source>
        <translation>&amp;Tisk…</translation>
    </message>
    <message>
        <source>Print Pre&amp;view…</source>
        <translation>Ná&amp;hled tisku…</translation>
    </message>
    <message>
        <source>Ctrl+Alt+P</source>
        <translation>Ctrl+Alt+P</translation>
    </message>
    <message>
        <source>Print to P&amp;DF…</source>
        <translation>Tisk do &amp;PDF…</translation>
    </message>
    <message>
        <source>Print to PDF</source>
        <translation>Tisk do PDF</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Dokument PDF (*.pdf)</translation>
    </message>
    <message>
        <source>&amp;Export Figure…</source>
        <translation>&amp;Exportovat obrázek…</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Export &amp;Points…</source>
        <translation>Exportovat &amp;body…</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Konec</translation>
    </message>
    <message>
        <source>Pre&amp;ferences…</source>
        <translation>&amp;Předvolby…</translation>
    </message>
    <message>
        <source>Copy Matrices as &amp;LaTeX</source>
        <translation>Kopírovat matice jako &amp;LaTeX</translation>
    </message>
    <message>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <source>The current item has no matrices.</source>
        <translation>Aktuální položka nemá žádné matice.</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n matrices as LaTeX (amsmath bmatrix).</source>
        <translation>
            <numerusform>Zkopírována %n matice jako LaTeX (amsmath bmatrix).</numerusform>
            <numerusform>Zkopírovány %n matice jako LaTeX (amsmath bmatrix).</numerusform>
            <numerusform>Zkopírováno %n matic jako LaTeX (amsmath bmatrix).</numerusform>
        </translation>
    </message>
    <message>
        <source>D&amp;uplicate Item</source>
        <translation>&amp;Duplikovat položku</translation>
    </message>
    <message>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <source>&amp;Delete Item</source>
        <translation>&amp;Odstranit položku</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>Př&amp;iblížit</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>O&amp;ddálit</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>Přizpůsobit &amp;oknu</translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <source>&amp;Stop Drawing</source>
        <translation>Zastavit &amp;kreslení</translation>
    </message>
    <message>
        <source>&amp;Draw Again</source>
        <translation>&amp;Překreslit</translation>
    </message>
    <message>
        <source>&amp;Play/Pause Animation</source>
        <translation>Pře&amp;hrát/pozastavit animaci</translation>
    </message>
    <message>
        <source>S&amp;top Animation</source>
        <translation>Zastavit a&amp;nimaci</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>Obnovit rozlož&amp;ení</translation>
    </message>
    <message>
        <source>&amp;About Attractor Workbench</source>
        <translation>&amp;O aplikaci Attractor Workbench</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>O &amp;Qt</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Uživatelská příručka</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Zpět</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>Z&amp;novu</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Zpět</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Znovu</translation>
    </message>
    <message>
        <source>Nothing to %1 (%2)</source>
        <translation>Žádná akce pro „%1“ (%2)</translation>
    </message>
    <message>
        <source>%1 %2 (%3)</source>
        <translation>%1 %2 (%3)</translation>
    </message>
    <message>
        <source>&amp;Control Polygon</source>
        <translation>Řídi&amp;cí polygon</translation>
    </message>
    <message>
        <source>Control &amp;Net (3D)</source>
        <translation>Řídicí &amp;síť (3D)</translation>
    </message>
    <message>
        <source>Subdivided &amp;Mesh (3D)</source>
        <translation>&amp;Zjemněná síť (3D)</translation>
    </message>
    <message>
        <source>&amp;Attractor (3D)</source>
        <translation>&amp;Atraktor (3D)</translation>
    </message>
    <message>
        <source>A&amp;xes (3D)</source>
        <translation>Os&amp;y (3D)</translation>
    </message>
    <message>
        <source>&amp;Bounding Box (3D)</source>
        <translation>Ohraniču&amp;jící kvádr (3D)</translation>
    </message>
    <message>
        <source>&amp;Perspective (3D)</source>
        <translation>Pe&amp;rspektiva (3D)</translation>
    </message>
    <message>
        <source>&amp;Start Set</source>
        <translation>Počáteční mno&amp;žina</translation>
    </message>
    <message>
        <source>&amp;Exact Curve</source>
        <translation>Přesná kři&amp;vka</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>&amp;Mřížka</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Vlastnosti</translation>
    </message>
    <message>
        <source>Undo History</source>
        <translation>Historie úprav</translation>
    </message>
    <message>
        <source>Spectrum</source>
        <translation>Spektrum</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>Matice</translation>
    </message>
    <message>
        <source>Analysis</source>
        <translation>Analýza</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresa</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animace</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Soubor</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Otevřít ne&amp;dávné</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>Úpr&amp;avy</translation>
    </message>
    <message>
        <source>&amp;Item</source>
        <translation>&amp;Položka</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>&amp;Přidat</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Zobrazit</translation>
    </message>
    <message>
        <source>Four-point &amp;Regularity Chart…</source>
        <translation>&amp;Graf regularity čtyřbodového schématu…</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Nápověda</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Hlavní</translation>
    </message>
    <message>
        <source> Hutchinson step: </source>
        <translation> Hutchinsonův krok: </translation>
    </message>
    <message>
        <source>off</source>
        <translation>vyp.</translation>
    </message>
    <message>
        <source>  Subdivision steps: </source>
        <translation>  Kroky subdivize: </translation>
    </message>
    <message>
        <source>Classic subdivision polygons beside the IFS attractor</source>
        <translation>Klasické subdivizní polygony vedle atraktoru IFS</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Bez názvu</translation>
    </message>
    <message>
        <source>%1[*] — Attractor Workbench</source>
        <translation>%1[*] — Attractor Workbench</translation>
    </message>
    <message>
        <source>Cubic B-spline</source>
        <translation>Kubický B-spline</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Otevřít projekt</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Otevřeno: %1</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Uložit projekt</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Uloženo: %1</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Neuložené změny</translation>
    </message>
    <message>
        <source>The project &quot;%1&quot; has unsaved changes. Save them?</source>
        <translation>Projekt „%1“ obsahuje neuložené změny. Chcete je uložit?</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Uložit projekt jako</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Vrátit k uloženému</translation>
    </message>
    <message>
        <source>Discard all changes and reload %1?</source>
        <translation>Zahodit všechny změny a znovu načíst %1?</translation>
    </message>
    <message>
        <source>Printing cancelled.</source>
        <translation>Tisk zrušen.</translation>
    </message>
    <message>
        <source>Print</source>
        <translation>Tisk</translation>
    </message>
    <message>
        <source>The printer could not be started.</source>
        <translation>Tiskárnu nelze spustit.</translation>
    </message>
    <message>
        <source>A .tex file holds the matrices only: choose the Matrices view, or .png, .svg or .pdf for a picture.</source>
        <translation>Soubor .tex obsahuje pouze matice: zvolte pohled Matice, nebo pro obrázek .png, .svg či .pdf.</translation>
    </message>
    <message>
        <source>The current item has no matrices to export.</source>
        <translation>Aktuální položka nemá žádné matice k exportu.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>%1 nelze zapsat: %2.</translation>
    </message>
    <message>
        <source>Unknown format &quot;%1&quot;: use .png, .svg or .pdf (.tex for the matrices).</source>
        <translation type="vanished">Neznámý formát „%1“: použijte .png, .svg nebo .pdf (.tex pro matice).</translation>
    </message>
    <message>
        <source>Exporting %1 was cancelled while the attractor was drawn.</source>
        <translation>Export %1 byl zrušen během kreslení atraktoru.</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="vanished">Exportováno: %1</translation>
    </message>
    <message>
        <source>About Attractor Workbench</source>
        <translation>O aplikaci Attractor Workbench</translation>
    </message>
    <message>
        <source>Attractor Workbench %1

Subdivision curves as attractors of iterated function systems: control points, subdivision matrices, spectra and figures.</source>
        <translation>Attractor Workbench %1

Subdivizní křivky jako atraktory iterovaných funkčních systémů: řídicí body, subdivizní matice, spektra a obrázky.</translation>
    </message>
    <message>
        <source>Spectra of %1</source>
        <translation>Spektra položky %1</translation>
    </message>
    <message>
        <source>Bicubic B-spline</source>
        <translation>Bikubický B-spline</translation>
    </message>
    <message>
        <source>Loop (box spline)</source>
        <translation>Loop (box spline)</translation>
    </message>
    <message>
        <source>Kobbelt √3</source>
        <translation>Kobbelt √3</translation>
    </message>
    <message>
        <source>%1, %2 layout</source>
        <translation>%1, rozložení %2</translation>
    </message>
    <message>
        <source>%1 surface</source>
        <translation>Plocha %1</translation>
    </message>
    <message>
        <source>duplicate</source>
        <translation>duplikát</translation>
    </message>
    <message>
        <source>Duplicate Item</source>
        <translation>Duplikovat položku</translation>
    </message>
    <message>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <source>an unsaved project</source>
        <translation>neuloženého projektu</translation>
    </message>
    <message>
        <source>Recover Project</source>
        <translation>Obnovit projekt</translation>
    </message>
    <message>
        <source>Attractor Workbench did not shut down properly. A recovery copy of %1 from %2 exists. Recover it? (Discard deletes the copy.)</source>
        <translation>Attractor Workbench nebyl řádně ukončen. Existuje záložní kopie %1 z %2. Chcete ji obnovit? (Zahodit kopii smaže.)</translation>
    </message>
    <message>
        <source>The recovery copy cannot be read: %1</source>
        <translation>Záložní kopii nelze přečíst: %1</translation>
    </message>
    <message>
        <source>The recovery copy cannot be read: %1

It was kept as %2.</source>
        <translation>Záložní kopii nelze přečíst: %1

Byla ponechána jako %2.</translation>
    </message>
    <message>
        <source>Export Points</source>
        <translation>Exportovat body</translation>
    </message>
    <message>
        <source>The current item has no attractor whose points could be exported.</source>
        <translation>Aktuální položka nemá atraktor, jehož body by bylo možné exportovat.</translation>
    </message>
    <message>
        <source>Exported the points to %1</source>
        <translation>Body exportovány do %1</translation>
    </message>
    <message>
        <source>The current item has no attractor.</source>
        <translation>Aktuální položka nemá atraktor.</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Jazyk</translation>
    </message>
    <message>
        <source>System Default</source>
        <translation>Podle systému</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Jazyk</translation>
    </message>
    <message>
        <source>The language changes when Attractor Workbench is started again.</source>
        <translation>Jazyk se změní po dalším spuštění Attractor Workbench.</translation>
    </message>
    <message>
        <source>Built with Qt %1 (running on Qt %2), Eigen %3 and QCustomPlot %4.</source>
        <translation>Sestaveno s Qt %1 (spuštěno na Qt %2), Eigen %3 a QCustomPlot %4.</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>Open E&amp;xample</source>
        <translation>Otevřít pří&amp;klad</translation>
    </message>
    <message>
        <source>Draw Fᵏ(X₀) of the start set X₀ as vectors</source>
        <translation>Kreslit Fᵏ(X₀) počáteční množiny X₀ vektorově</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>bez-nazvu</translation>
    </message>
    <message>
        <source>No examples installed</source>
        <translation>Žádné příklady nejsou nainstalovány</translation>
    </message>
    <message>
        <source>Open Example</source>
        <translation>Otevřít příklad</translation>
    </message>
    <message>
        <source>Opened the example %1 (a copy: Save As keeps it)</source>
        <translation>Otevřen příklad %1 (kopie: Uložit jako ji zachová)</translation>
    </message>
    <message>
        <source>Projects and figures with their item (*.awb *.png *.svg);;Attractor Workbench projects (*.awb);;Exported figures (*.png *.svg);;All files (*)</source>
        <translation type="vanished">Projekty a obrázky s položkou (*.awb *.png *.svg);;Projekty Attractor Workbench (*.awb);;Exportované obrázky (*.png *.svg);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>&amp;Import Mesh…</source>
        <translation>&amp;Importovat síť…</translation>
    </message>
    <message>
        <source>Import Mesh</source>
        <translation>Importovat síť</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.off *.ply);;Wavefront OBJ (*.obj);;OFF (*.off);;PLY (*.ply)</source>
        <translation>Sítě (*.obj *.off *.ply);;Wavefront OBJ (*.obj);;OFF (*.off);;PLY (*.ply)</translation>
    </message>
    <message>
        <source>Catmull–Clark (any polygons)</source>
        <translation>Catmull–Clark (libovolné mnohoúhelníky)</translation>
    </message>
    <message>
        <source>Loop (triangles only)</source>
        <translation>Loop (jen trojúhelníky)</translation>
    </message>
    <message>
        <source>Subdivision scheme:</source>
        <translation>Schéma subdivize:</translation>
    </message>
    <message>
        <source>Cube (Catmull–Clark)</source>
        <translation>Krychle (Catmull–Clark)</translation>
    </message>
    <message>
        <source>Tetrahedron (Loop)</source>
        <translation>Čtyřstěn (Loop)</translation>
    </message>
    <message>
        <source>Octahedron (Loop)</source>
        <translation>Osmistěn (Loop)</translation>
    </message>
    <message>
        <source>Icosahedron (Loop)</source>
        <translation>Dvacetistěn (Loop)</translation>
    </message>
    <message>
        <source>Pentagonal prism (Catmull–Clark)</source>
        <translation>Pětiboký hranol (Catmull–Clark)</translation>
    </message>
    <message>
        <source>Open grid (Catmull–Clark)</source>
        <translation>Otevřená mřížka (Catmull–Clark)</translation>
    </message>
    <message>
        <source>Grid of mixed diagonals (Loop)</source>
        <translation>Mřížka se smíšenými úhlopříčkami (Loop)</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Vrchol</translation>
    </message>
    <message>
        <source>Valences</source>
        <translation>Valence</translation>
    </message>
    <message>
        <source>%1: its spectrum, verdict and characteristic map are in the Spectrum, Matrices and Analysis docks</source>
        <translation>%1: jeho spektrum, verdikt a charakteristické zobrazení najdete v panelech Spektrum, Matice a Analýza</translation>
    </message>
    <message>
        <source>Export &amp;Mesh…</source>
        <translation>Exportovat &amp;síť…</translation>
    </message>
    <message>
        <source>Export Mesh writes a mesh surface; %1 is a %2</source>
        <translation>„Exportovat síť“ zapisuje plochu ze sítě; %1 je typu %2</translation>
    </message>
    <message>
        <source>Export Mesh writes a mesh surface: choose one first</source>
        <translation>„Exportovat síť“ zapisuje plochu ze sítě: nejprve nějakou vyberte</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 nelze zapsat: %2</translation>
    </message>
    <message>
        <source>Export Mesh</source>
        <translation>Exportovat síť</translation>
    </message>
    <message>
        <source>Steps of %1 before every vertex is moved to its limit position:</source>
        <translation>Počet kroků schématu %1 před přesunem každého vrcholu do jeho limitní polohy:</translation>
    </message>
    <message>
        <source>Wavefront OBJ (*.obj)</source>
        <translation>Wavefront OBJ (*.obj)</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Zapsáno: %1</translation>
    </message>
    <message>
        <source>Copy Matrices as &amp;MATLAB</source>
        <translation>Kopírovat matice jako &amp;MATLAB</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n matrices as MATLAB cell arrays (for jsr() of the JSR toolbox).</source>
        <translation>
            <numerusform>Zkopírována %n matice jako pole buněk MATLABu (pro jsr() z JSR toolboxu).</numerusform>
            <numerusform>Zkopírovány %n matice jako pole buněk MATLABu (pro jsr() z JSR toolboxu).</numerusform>
            <numerusform>Zkopírováno %n matic jako pole buněk MATLABu (pro jsr() z JSR toolboxu).</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>I&amp;mportovat…</translation>
    </message>
    <message>
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <source>Export &amp;Item As…</source>
        <translation>Exportovat po&amp;ložku jako…</translation>
    </message>
    <message>
        <source>%1: no entry could be imported</source>
        <translation>%1: nepodařilo se importovat žádný záznam</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importovat %1</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Import</translation>
    </message>
    <message>
        <source>Everything Attractor Workbench imports (*.ifs *.obj *.off *.ply);;Fractint IFS (*.ifs);;Meshes (*.obj *.off *.ply)</source>
        <translation type="vanished">Vše, co Attractor Workbench umí importovat (*.ifs *.obj *.off *.ply);;Fractint IFS (*.ifs);;Sítě (*.obj *.off *.ply)</translation>
    </message>
    <message>
        <source>Imported the other entries; these were left out:</source>
        <translation type="vanished">Ostatní záznamy byly importovány; tyto byly vynechány:</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>Importováno: %1</translation>
    </message>
    <message>
        <source>Export Item As writes an item with maps: choose one first</source>
        <translation>„Exportovat položku jako“ zapisuje položku se zobrazeními: nejprve nějakou vyberte</translation>
    </message>
    <message>
        <source>%1 has no matrices to export</source>
        <translation>%1 nemá žádné matice k exportu</translation>
    </message>
    <message>
        <source>%1: Export Item As writes .ifs (Fractint) or .m (MATLAB) files</source>
        <translation type="vanished">%1: „Exportovat položku jako“ zapisuje soubory .ifs (Fractint) nebo .m (MATLAB)</translation>
    </message>
    <message>
        <source>Export Item As</source>
        <translation>Exportovat položku jako</translation>
    </message>
    <message>
        <source>Fractint IFS (*.ifs);;MATLAB cell arrays of the matrices (*.m)</source>
        <translation type="vanished">Fractint IFS (*.ifs);;Matice jako pole buněk MATLABu (*.m)</translation>
    </message>
    <message>
        <source>Everything Attractor Workbench imports (*.ifs *.flame *.flam3 *.obj *.off *.ply);;Fractint IFS (*.ifs);;Fractal flames: flam3, Apophysis, JWildfire (*.flame *.flam3);;Meshes (*.obj *.off *.ply)</source>
        <translation>Vše, co Attractor Workbench importuje (*.ifs *.flame *.flam3 *.obj *.off *.ply);;IFS Fractint (*.ifs);;Fraktální plameny: flam3, Apophysis, JWildfire (*.flame *.flam3);;Sítě (*.obj *.off *.ply)</translation>
    </message>
    <message>
        <source>Imported the others; these were left out:</source>
        <translation>Ostatní byly importovány; tyto byly vynechány:</translation>
    </message>
    <message>
        <source>Imported with these losses:</source>
        <translation>Importováno s těmito ztrátami:</translation>
    </message>
    <message>
        <source>%1: Export Item As writes .ifs (Fractint), .flame (flam3) or .m (MATLAB) files</source>
        <translation>%1: „Exportovat položku jako“ zapisuje soubory .ifs (Fractint), .flame (flam3) nebo .m (MATLAB)</translation>
    </message>
    <message>
        <source>Fractint IFS (*.ifs);;Fractal flame for flam3-render, Apophysis, JWildfire (*.flame);;MATLAB cell arrays of the matrices (*.m)</source>
        <translation>IFS Fractint (*.ifs);;Fraktální plamen pro flam3-render, Apophysis, JWildfire (*.flame);;Pole buněk MATLABu s maticemi (*.m)</translation>
    </message>
    <message>
        <source>An .exr file holds the raw density of an attractor drawn in the plane: choose the Attractor view of such an item.</source>
        <translation>Soubor .exr obsahuje surovou hustotu atraktoru kresleného v rovině: zvolte pohled Atraktor takové položky.</translation>
    </message>
    <message>
        <source>Unknown format &quot;%1&quot;: use .png, .svg or .pdf (.tex for the matrices, .exr for the attractor&apos;s raw density).</source>
        <translation>Neznámý formát „%1“: použijte .png, .svg nebo .pdf (.tex pro matice, .exr pro surovou hustotu atraktoru).</translation>
    </message>
    <message>
        <source>Projects and figures with their item (*.awb *.png *.svg);;Attractor Workbench projects (*.awb);;Exported figures (*.png *.svg);;Other tools&apos; IFS files, as a new project (*.ifs *.flame *.flam3);;All files (*)</source>
        <translation>Projekty a obrázky s položkou (*.awb *.png *.svg);;Projekty Attractor Workbench (*.awb);;Exportované obrázky (*.png *.svg);;Soubory IFS jiných nástrojů jako nový projekt (*.ifs *.flame *.flam3);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Nástroje</translation>
    </message>
    <message>
        <source>Python Console</source>
        <translation>Konzole Pythonu</translation>
    </message>
    <message>
        <source>Save &amp;Recording…</source>
        <translation>Uložit &amp;záznam…</translation>
    </message>
    <message>
        <source>Save the edits since the project was opened as a Python script that replays them on the file</source>
        <translation>Uložit úpravy od otevření projektu jako skript v Pythonu, který je na souboru přehraje</translation>
    </message>
    <message>
        <source>&amp;Clear Recording</source>
        <translation>&amp;Vymazat záznam</translation>
    </message>
    <message>
        <source>Start the recording again from the document as it is now</source>
        <translation>Začít záznam znovu od dokumentu v současném stavu</translation>
    </message>
    <message>
        <source>Save Recording</source>
        <translation>Uložit záznam</translation>
    </message>
    <message>
        <source>Python scripts (*.py)</source>
        <translation>Skripty Pythonu (*.py)</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n recorded edit(s) to %1</source>
        <translation>
            <numerusform>Uložena %n zaznamenaná úprava do %1</numerusform>
            <numerusform>Uloženy %n zaznamenané úpravy do %1</numerusform>
            <numerusform>Uloženo %n zaznamenaných úprav do %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Run Python &amp;Script…</source>
        <translation>Spustit &amp;skript v Pythonu…</translation>
    </message>
    <message>
        <source>Run a Python script on the open document, in the Python console</source>
        <translation>Spustit skript v Pythonu na otevřeném dokumentu v konzoli Pythonu</translation>
    </message>
    <message>
        <source>Run Python Script</source>
        <translation>Spustit skript v Pythonu</translation>
    </message>
    <message>
        <source>&amp;Gallery…</source>
        <translation>&amp;Galerie…</translation>
    </message>
    <message>
        <source>The examples as thumbnails: the papers&apos; figures, meshes, masks</source>
        <translation>Příklady jako náhledy: obrázky z článků, sítě, masky</translation>
    </message>
    <message>
        <source>Exported the figure to %1</source>
        <translation>Obrázek exportován do %1</translation>
    </message>
    <message>
        <source>000 Schaefer, Levin, Goldman: Subdivision Schemes and Attractors</source>
        <translation>000 Schaefer, Levin, Goldman: Subdivizní schémata a atraktory</translation>
    </message>
    <message>
        <source>001 Li et al.: Normal Vector Based Subdivision</source>
        <translation>001 Li a kol.: Subdivize založená na normálových vektorech</translation>
    </message>
    <message>
        <source>002 John: All Bézier Curves Are Attractors</source>
        <translation>002 John: Všechny Bézierovy křivky jsou atraktory</translation>
    </message>
    <message>
        <source>003 BCIFS Junction Curves</source>
        <translation>003 Křivky napojení BCIFS</translation>
    </message>
    <message>
        <source>004 Ptáčková: Fractals and Splines</source>
        <translation>004 Ptáčková: Fraktály a spliny</translation>
    </message>
    <message>
        <source>Meshes</source>
        <translation>Sítě</translation>
    </message>
    <message>
        <source>Masks, Animations and Other Tools&apos; Files</source>
        <translation>Masky, animace a soubory jiných programů</translation>
    </message>
    <message>
        <source>All %1 faces are triangles: Loop keeps them triangles (Catmull–Clark would make each one three quads around a new valence-3 vertex).

Subdivision scheme:</source>
        <translation>Všechny stěny (%1) jsou trojúhelníky: Loop je zachová jako trojúhelníky (Catmull–Clark by z každé udělal tři čtyřúhelníky kolem nového vrcholu valence 3).

Schéma subdivize:</translation>
    </message>
    <message>
        <source>Regularity &amp;Atlas…</source>
        <translation>&amp;Atlas regularity…</translation>
    </message>
    <message>
        <source>Where the selected curve&apos;s family of schemes is C^k, over one or two of its parameters (on a Dask cluster)</source>
        <translation>Kde je rodina schémat vybrané křivky C^k, v závislosti na jednom nebo dvou jejích parametrech (na clusteru Dask)</translation>
    </message>
    <message>
        <source>Automaton</source>
        <translation>Automat</translation>
    </message>
    <message>
        <source>Edge %1–%2: sharpness %3 (Item &gt; Crease Edge… changes it)</source>
        <translation>Hrana %1–%2: ostrost %3 (změní ji Položka &gt; Ostrá hrana…)</translation>
    </message>
    <message>
        <source>&amp;Crease Edge…</source>
        <translation>&amp;Ostrá hrana…</translation>
    </message>
    <message>
        <source>The sharpness of the mesh edge clicked in the 3D view</source>
        <translation>Ostrost hrany sítě, na kterou jste klikli ve 3D pohledu</translation>
    </message>
    <message>
        <source>Sharpen &amp;Vertex…</source>
        <translation>Zostřit &amp;vrchol…</translation>
    </message>
    <message>
        <source>The corner sharpness of the mesh vertex clicked in the 3D view</source>
        <translation>Ostrost rohu ve vrcholu sítě, na který jste klikli ve 3D pohledu</translation>
    </message>
    <message>
        <source>Sharp features belong to mesh surfaces: choose one first</source>
        <translation>Ostré prvky patří plochám ze sítí: nejdříve jednu vyberte</translation>
    </message>
    <message>
        <source>Click an edge of the control mesh in the 3D view first</source>
        <translation>Nejdříve klikněte ve 3D pohledu na hranu řídicí sítě</translation>
    </message>
    <message>
        <source>Click a vertex of the control mesh in the 3D view first</source>
        <translation>Nejdříve klikněte ve 3D pohledu na vrchol řídicí sítě</translation>
    </message>
    <message>
        <source>Crease Edge</source>
        <translation>Ostrá hrana</translation>
    </message>
    <message>
        <source>Sharpness of the edge from vertex %1 to vertex %2 (0: smooth; the crease rules for that many levels; 10: for ever):</source>
        <translation>Ostrost hrany z vrcholu %1 do vrcholu %2 (0: hladká; pravidla ostré hrany po tolik úrovní; 10: navždy):</translation>
    </message>
    <message>
        <source>Sharpen Vertex</source>
        <translation>Zostřit vrchol</translation>
    </message>
    <message>
        <source>Sharpness of vertex %1 (0: smooth; a corner for that many levels; 10: for ever):</source>
        <translation>Ostrost vrcholu %1 (0: hladký; roh po tolik úrovní; 10: navždy):</translation>
    </message>
    <message>
        <source>Not repaired: %1</source>
        <translation>Neopraveno: %1</translation>
    </message>
    <message>
        <source>%1

Repair the mesh? These changes are well defined:

%2</source>
        <translation>%1

Opravit síť? Tyto změny jsou jednoznačně definované:

%2</translation>
    </message>
    <message>
        <source>Even repaired: %1</source>
        <translation>Ani po opravě: %1</translation>
    </message>
    <message>
        <source>Repaired: %1</source>
        <translation>Opraveno: %1</translation>
    </message>
    <message>
        <source>Imported with these losses and changes:</source>
        <translation>Importováno s těmito ztrátami a změnami:</translation>
    </message>
    <message>
        <source>The mesh is %1.

Repair it instead? These changes are well defined:

%2

No imports it as it is.</source>
        <translation>Síť je %1.

Má se místo toho opravit? Tyto změny jsou dobře definované:

%2

Ne ji importuje tak, jak je.</translation>
    </message>
    <message>
        <source>The mesh is %1.</source>
        <translation>Síť je %1.</translation>
    </message>
    <message>
        <source>Face %1: a hole (Item &gt; Toggle Hole fills it)</source>
        <translation>Stěna %1: díra (Položka &gt; Přepnout díru ji vyplní)</translation>
    </message>
    <message>
        <source>Face %1 (Item &gt; Toggle Hole makes it a hole)</source>
        <translation>Stěna %1 (Položka &gt; Přepnout díru z ní udělá díru)</translation>
    </message>
    <message>
        <source>Toggle &amp;Hole</source>
        <translation>Přepnout &amp;díru</translation>
    </message>
    <message>
        <source>Make the mesh face clicked in the 3D view a hole, or fill it</source>
        <translation>Udělá ze stěny sítě kliknuté ve 3D pohledu díru, nebo ji vyplní</translation>
    </message>
    <message>
        <source>Click inside a face of the control mesh in the 3D view first</source>
        <translation>Nejprve klikněte dovnitř stěny řídicí sítě ve 3D pohledu</translation>
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
        <translation>%1 %2 %3i (modul %4)</translation>
    </message>
    <message>
        <source>Sum of row %1: %2</source>
        <translation>Součet řádku %1: %2</translation>
    </message>
    <message>
        <source>Sum of column %1: %2</source>
        <translation>Součet sloupce %1: %2</translation>
    </message>
    <message>
        <source>“%1” is not a finite number: %2, row %3, column %4 was not changed.</source>
        <translation>„%1“ není konečné číslo: %2, řádek %3, sloupec %4 nebyl změněn.</translation>
    </message>
    <message>
        <source>A block</source>
        <translation>blok A</translation>
    </message>
    <message>
        <source>b row</source>
        <translation>řádek b</translation>
    </message>
    <message>
        <source>fixed part of the lifted map</source>
        <translation>pevná část zdviženého zobrazení</translation>
    </message>
    <message>
        <source>— &lt;span style=&apos;background:#e2ecfa&apos;&gt;&amp;nbsp;A&amp;nbsp;&lt;/span&gt; block, &lt;span style=&apos;background:#fcecd6&apos;&gt;&amp;nbsp;b&amp;nbsp;&lt;/span&gt; row</source>
        <translation>— blok &lt;span style=&apos;background:#e2ecfa&apos;&gt;&amp;nbsp;A&amp;nbsp;&lt;/span&gt;, řádek &lt;span style=&apos;background:#fcecd6&apos;&gt;&amp;nbsp;b&amp;nbsp;&lt;/span&gt;</translation>
    </message>
    <message>
        <source>(complex entries)</source>
        <translation>(komplexní prvky)</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Odebrat</translation>
    </message>
    <message>
        <source>Remove the map %1 from the IFS (one undo step)</source>
        <translation>Odebrat zobrazení %1 z IFS (jeden krok zpět)</translation>
    </message>
    <message>
        <source>Add a Map</source>
        <translation>Přidat zobrazení</translation>
    </message>
    <message>
        <source>A new map S_(p+1), a copy of the last one to edit cell by cell (one undo step)</source>
        <translation>Nové zobrazení S_(p+1), kopie posledního k úpravě buňku po buňce (jeden krok zpět)</translation>
    </message>
</context>
<context>
    <name>awb::MeshInputs</name>
    <message>
        <source>%1 vertices; a mesh item takes at most %2</source>
        <translation>%1 vrcholů; položka se sítí jich pojme nejvýše %2</translation>
    </message>
    <message>
        <source>%1 faces; a mesh item takes at most %2</source>
        <translation>%1 stěn; položka se sítí jich pojme nejvýše %2</translation>
    </message>
</context>
<context>
    <name>awb::Messages</name>
    <message>
        <source>… and %1 more lines: Show Details… lists them all.</source>
        <translation>… a dalších řádků: %1. Všechny je vypíše tlačítko „Ukázat podrobnosti…“.</translation>
    </message>
    <message>
        <source>Show Details… shows the whole text.</source>
        <translation>Celý text zobrazí tlačítko „Ukázat podrobnosti…“.</translation>
    </message>
</context>
<context>
    <name>awb::MoveControlPointsCommand</name>
    <message numerus="yes">
        <source>Move %n control points of %1</source>
        <translation>
            <numerusform>Přesunout %n řídicí bod položky %1</numerusform>
            <numerusform>Přesunout %n řídicí body položky %1</numerusform>
            <numerusform>Přesunout %n řídicích bodů položky %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Move a control point of %1</source>
        <translation>Přesunout řídicí bod položky %1</translation>
    </message>
</context>
<context>
    <name>awb::MoveItemCommand</name>
    <message>
        <source>Move %1</source>
        <translation>Přesunout %1</translation>
    </message>
</context>
<context>
    <name>awb::NormalVectorItem</name>
    <message>
        <source>Normal-vector curve</source>
        <translation>Křivka normálových vektorů</translation>
    </message>
    <message>
        <source>Change normal-vector scheme of %1</source>
        <translation>Změnit schéma normálových vektorů položky %1</translation>
    </message>
    <message>
        <source>the normal-vector scheme is not linear: it has no subdivision matrices (001 eq. (1))</source>
        <translation>schéma normálových vektorů není lineární: nemá subdivizní matice (001 eq. (1))</translation>
    </message>
    <message>
        <source>No equivalent IFS: %1</source>
        <translation>Žádný ekvivalentní IFS: %1</translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation type="vanished">očekáváno true nebo false</translation>
    </message>
    <message>
        <source>expected an array of sign rules</source>
        <translation>očekáváno pole pravidel pro znaménka</translation>
    </message>
    <message>
        <source>expected one of &quot;%1&quot;</source>
        <translation>očekávána jedna z hodnot „%1“</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Own rules</source>
        <translation>Vlastní pravidla</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Kroky</translation>
    </message>
    <message>
        <source>Subdivision steps of the polygon shown</source>
        <translation>Kroky subdivize zobrazeného polygonu</translation>
    </message>
    <message>
        <source>Normal direction</source>
        <translation>Směr normály</translation>
    </message>
    <message>
        <source>Counter-clockwise (positive)</source>
        <translation>Proti směru hodinových ručiček (kladný)</translation>
    </message>
    <message>
        <source>Clockwise (negative)</source>
        <translation>Po směru hodinových ručiček (záporný)</translation>
    </message>
    <message>
        <source>Closed polygon</source>
        <translation>Uzavřený polygon</translation>
    </message>
    <message>
        <source>α%1</source>
        <translation>α%1</translation>
    </message>
    <message>
        <source>Rules</source>
        <translation>Pravidla</translation>
    </message>
    <message>
        <source>Position of new point %1 along the edge (001 eq. (1))</source>
        <translation type="vanished">Poloha nového bodu %1 podél hrany (001 eq. (1))</translation>
    </message>
    <message>
        <source>β%1</source>
        <translation>β%1</translation>
    </message>
    <message>
        <source>Displacement of new point %1 along the normal</source>
        <translation type="vanished">Posunutí nového bodu %1 ve směru normály</translation>
    </message>
    <message>
        <source>Signs of β</source>
        <translation>Znaménka β</translation>
    </message>
    <message>
        <source>How the sign of β alternates: &quot;constant&quot;, &quot;edge-alternating&quot;, &quot;level-edge-alternating&quot; or &quot;level-alternating&quot;; none, one, or one per rule</source>
        <translation>Jak se střídá znaménko β: &quot;constant&quot;, &quot;edge-alternating&quot;, &quot;level-edge-alternating&quot; nebo &quot;level-alternating&quot;; žádné, jedno, nebo jedno pro každé pravidlo</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Řídicí body</translation>
    </message>
</context>
<context>
    <name>awb::NormalVectorSpec</name>
    <message>
        <source>unknown preset &quot;%1&quot;</source>
        <translation>neznámá předvolba „%1“</translation>
    </message>
    <message>
        <source>%1 steps: at least 0 and at most %2 are allowed</source>
        <translation>počet kroků %1: povoleno je 0 až %2</translation>
    </message>
    <message>
        <source>need at least 2 rules (p &gt;= 2), got %1</source>
        <translation>jsou potřeba alespoň 2 pravidla (p &gt;= 2), zadáno %1</translation>
    </message>
    <message>
        <source>%1 values of beta for %2 of alpha: need one per rule</source>
        <translation>počet hodnot beta (%1) neodpovídá počtu hodnot alfa (%2): pro každé pravidlo je potřeba jedna</translation>
    </message>
    <message>
        <source>%1 signs for %2 rules: give none, one, or one per rule</source>
        <translation>počet znamének (%1) neodpovídá počtu pravidel (%2): zadejte žádné, jedno, nebo jedno pro každé pravidlo</translation>
    </message>
    <message>
        <source>%1_%2 is not a finite number</source>
        <translation>%1_%2 není konečné číslo</translation>
    </message>
</context>
<context>
    <name>awb::PaletteDialog</name>
    <message>
        <source>Map Colours</source>
        <translation>Barvy zobrazení</translation>
    </message>
    <message>
        <source>The colour of the points each map f&lt;sub&gt;i&lt;/sub&gt; makes (Style: colour by map or by address).</source>
        <translation>Barva bodů, které vytváří jednotlivá zobrazení f&lt;sub&gt;i&lt;/sub&gt; (Styl: barva podle zobrazení nebo podle adresy).</translation>
    </message>
    <message>
        <source>Colour of map %1</source>
        <translation>Barva zobrazení %1</translation>
    </message>
    <message>
        <source>Map %1:</source>
        <translation>Zobrazení %1:</translation>
    </message>
    <message>
        <source>Use the &amp;Default Colours</source>
        <translation>Použít &amp;výchozí barvy</translation>
    </message>
</context>
<context>
    <name>awb::PointExport</name>
    <message>
        <source>cannot write the points: %1</source>
        <translation>body nelze zapsat: %1</translation>
    </message>
    <message>
        <source>--address needs an item drawn by one IFS; this one is drawn by an automaton</source>
        <translation>--address vyžaduje položku kreslenou jedním IFS; tato je kreslena automatem</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is drawn by an automaton: PLY export covers items with one IFS</source>
        <translation>„%1“ je kreslena automatem: export do PLY podporuje jen položky s jedním IFS</translation>
    </message>
    <message>
        <source>wrote %1 points, expected %2</source>
        <translation>zapsáno %1 bodů, očekáváno %2</translation>
    </message>
    <message>
        <source>this item is a fractal flame: its points come from its own chaos game, not from iterating maps (render its picture instead)</source>
        <translation>tato položka je fraktální plamen: její body pocházejí z vlastní hry chaosu, nikoli z iterace zobrazení (vykreslete raději její obrázek)</translation>
    </message>
</context>
<context>
    <name>awb::PointExportDialog</name>
    <message>
        <source>Export Points of %1</source>
        <translation>Exportovat body položky %1</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Procházet…</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Soubor:</translation>
    </message>
    <message>
        <source>CSV text: x, y[, z], map, view</source>
        <translation>Text CSV: x, y[, z], zobrazení, pohled</translation>
    </message>
    <message>
        <source>PLY point cloud: x, y, z, map colour, map</source>
        <translation>Mračno bodů PLY: x, y, z, barva zobrazení, zobrazení</translation>
    </message>
    <message>
        <source>F&amp;ormat:</source>
        <translation>F&amp;ormát:</translation>
    </message>
    <message>
        <source>The points of F^k(X0): every image of the start set&apos;s vertices after k steps of the Hutchinson operator</source>
        <translation>Body F^k(X0): všechny obrazy vrcholů počáteční množiny po k krocích Hutchinsonova operátoru</translation>
    </message>
    <message>
        <source>&amp;Depth k:</source>
        <translation>&amp;Hloubka k:</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportovat</translation>
    </message>
    <message>
        <source>Export Points</source>
        <translation>Exportovat body</translation>
    </message>
    <message>
        <source>CSV text (*.csv);;PLY point cloud (*.ply)</source>
        <translation>Text CSV (*.csv);;Mračno bodů PLY (*.ply)</translation>
    </message>
    <message>
        <source>The number of points depends on the automaton.</source>
        <translation>Počet bodů závisí na automatu.</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>Počet bodů: %1</translation>
    </message>
    <message>
        <source> — too many (at most %1): choose a smaller depth.</source>
        <translation> — příliš mnoho (nejvýše %1): zvolte menší hloubku.</translation>
    </message>
    <message>
        <source>%1 cannot be computed: %2</source>
        <translation>%1 nelze vypočítat: %2</translation>
    </message>
    <message>
        <source>Start set: %1</source>
        <translation>Počáteční množina: %1</translation>
    </message>
    <message>
        <source>Depth %1 gives %2 points, more than %3: choose a smaller depth.</source>
        <translation>Hloubka %1 dává %2 bodů, více než %3: zvolte menší hloubku.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 nelze zapsat: %2</translation>
    </message>
    <message>
        <source>Writing the points of %1…</source>
        <translation>Zapisování bodů položky %1…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Exporting the points was cancelled; nothing was written.</source>
        <translation>Export bodů byl zrušen; nic nebylo zapsáno.</translation>
    </message>
</context>
<context>
    <name>awb::PreferencesDialog</name>
    <message>
        <source>auto</source>
        <translation>automaticky</translation>
    </message>
</context>
<context>
    <name>awb::Project</name>
    <message>
        <source>Item</source>
        <translation>Položka</translation>
    </message>
    <message>
        <source>the name cannot be empty</source>
        <translation>název nemůže být prázdný</translation>
    </message>
    <message>
        <source>another item is already called &quot;%1&quot;</source>
        <translation>jiná položka se již jmenuje „%1“</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n items</source>
        <translation>
            <numerusform>Odstranit %n položku</numerusform>
            <numerusform>Odstranit %n položky</numerusform>
            <numerusform>Odstranit %n položek</numerusform>
        </translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>Přejmenovat %1 na %2</translation>
    </message>
    <message>
        <source>the project has no file name yet: use &quot;Save As&quot;</source>
        <translation>projekt zatím nemá název souboru: použijte „Uložit jako“</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>awb::ProjectIO</name>
    <message>
        <source>%1: cannot save: %2</source>
        <translation>%1: nelze uložit: %2</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1: nelze otevřít: %2</translation>
    </message>
    <message>
        <source>%1: the file is %2 MB; project files larger than %3 MB are refused (a project is at most a few MB)</source>
        <translation>%1: soubor má %2 MB; projektové soubory větší než %3 MB jsou odmítnuty (projekt má nejvýše několik MB)</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1: nelze číst: %2</translation>
    </message>
    <message>
        <source>%1: the file is empty</source>
        <translation>%1: soubor je prázdný</translation>
    </message>
    <message>
        <source>%1: the file holds only white space</source>
        <translation>%1: soubor obsahuje pouze bílé znaky</translation>
    </message>
    <message>
        <source>%1: the file is UTF-16 or UTF-32 text; project files are UTF-8 (save it again as UTF-8)</source>
        <translation>%1: soubor je text v kódování UTF-16 nebo UTF-32; projektové soubory jsou v UTF-8 (uložte jej znovu jako UTF-8)</translation>
    </message>
    <message>
        <source>%1: expected a JSON object at the top level</source>
        <translation>%1: na nejvyšší úrovni je očekáván objekt JSON</translation>
    </message>
    <message>
        <source>%1: not valid JSON: %2 at line %3, column %4</source>
        <translation>%1: neplatný JSON: %2 na řádku %3, sloupci %4</translation>
    </message>
    <message>
        <source>expected &quot;%1&quot;: this is not an Attractor Workbench project</source>
        <translation>očekáváno &quot;%1&quot;: toto není projekt Attractor Workbench</translation>
    </message>
    <message>
        <source>%1: the file has format version %2, written by a newer version of Attractor Workbench; this version reads format version %3 only. Please update the application.</source>
        <translation>%1: soubor má verzi formátu %2, zapsanou novější verzí Attractor Workbench; tato verze čte pouze verzi formátu %3. Aktualizujte prosím aplikaci.</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>chybí</translation>
    </message>
    <message>
        <source>expected an array</source>
        <translation>očekáváno pole</translation>
    </message>
    <message>
        <source>%1: field &quot;%2&quot;: %3</source>
        <translation>%1: pole &quot;%2&quot;: %3</translation>
    </message>
    <message>
        <source>item %1</source>
        <translation>položka %1</translation>
    </message>
    <message>
        <source>%1: %2: field &quot;%3&quot;: %4</source>
        <translation>%1: %2: pole &quot;%3&quot;: %4</translation>
    </message>
    <message>
        <source>field &quot;%1&quot;: %2</source>
        <translation>pole &quot;%1&quot;: %2</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>očekáván objekt</translation>
    </message>
    <message>
        <source>unknown item type %1; this version knows %2</source>
        <translation>neznámý typ položky %1; tato verze zná %2</translation>
    </message>
    <message>
        <source>another item is already called %1</source>
        <translation>jiná položka se již jmenuje %1</translation>
    </message>
    <message>
        <source>expected an array of items</source>
        <translation>očekáváno pole položek</translation>
    </message>
    <message>
        <source>expected an array of lifted points [x, y, c1, ...]</source>
        <translation>očekáváno pole zdvižených bodů [x, y, c1, ...]</translation>
    </message>
    <message>
        <source>expected a lifted point [x, y, c1, ...]</source>
        <translation>očekáván zdvižený bod [x, y, c1, ...]</translation>
    </message>
    <message>
        <source>expected an array of &quot;#rrggbb&quot; strings</source>
        <translation type="vanished">očekáváno pole řetězců &quot;#rrggbb&quot;</translation>
    </message>
    <message>
        <source>expected a string &quot;#rrggbb&quot;</source>
        <translation type="vanished">očekáván řetězec &quot;#rrggbb&quot;</translation>
    </message>
    <message>
        <source>a &quot;vertex-limits&quot; start set has no points (it starts at the limit positions of the mesh&apos;s vertices)</source>
        <translation>počáteční množina &quot;vertex-limits&quot; nemá body (začíná v limitních polohách vrcholů sítě)</translation>
    </message>
    <message>
        <source>the item</source>
        <translation>položka</translation>
    </message>
    <message>
        <source>expected an array of net point indices [0, 9, 18]</source>
        <translation>očekáváno pole indexů bodů sítě [0, 9, 18]</translation>
    </message>
    <message>
        <source>%1 net point indices; a start set takes at most %2</source>
        <translation>%1 indexů bodů sítě; počáteční množina jich smí mít nejvýše %2</translation>
    </message>
    <message>
        <source>expected a net point index (an integer from 0)</source>
        <translation>očekáván index bodu sítě (celé číslo od 0)</translation>
    </message>
</context>
<context>
    <name>awb::ProjectTreeModel</name>
    <message>
        <source>Name</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Druh</translation>
    </message>
    <message numerus="yes">
        <source>Move %n items</source>
        <translation>
            <numerusform>Přesunout %n položku</numerusform>
            <numerusform>Přesunout %n položky</numerusform>
            <numerusform>Přesunout %n položek</numerusform>
        </translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Přesunout %1</translation>
    </message>
</context>
<context>
    <name>awb::PropertiesWidget</name>
    <message>
        <source>Value refused</source>
        <translation>Hodnota odmítnuta</translation>
    </message>
    <message>
        <source>%1 cannot be set to %2.</source>
        <translation>%1 nelze nastavit na %2.</translation>
    </message>
    <message>
        <source>No item selected.</source>
        <translation>Není vybrána žádná položka.</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="vanished">&amp;Název:</translation>
    </message>
    <message>
        <source>The name is empty or already taken.</source>
        <translation type="vanished">Název je prázdný nebo již použitý.</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parametry</translation>
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
        <translation type="vanished">Počáteční množina X0</translation>
    </message>
    <message>
        <source>Point</source>
        <translation type="vanished">Bod</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation type="vanished">Úsečka</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation type="vanished">Trojúhelník</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation type="vanished">Mnohoúhelník</translation>
    </message>
    <message>
        <source>Points</source>
        <translation type="vanished">Body</translation>
    </message>
    <message>
        <source>Lifted points</source>
        <translation type="vanished">Zdvižené body</translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation type="vanished">Druh:</translation>
    </message>
    <message>
        <source>Drag its vertices in the attractor view.</source>
        <translation type="vanished">Její vrcholy přetáhněte v pohledu atraktoru.</translation>
    </message>
    <message>
        <source>Points of the lifted space of 000 §2: x, y, then the extra coordinates of the lifting, the homogeneous 1 implied. Commas between coordinates, &apos;;&apos; between points.</source>
        <translation type="vanished">Body zdviženého prostoru podle 000 §2: x, y a poté dodatečné souřadnice zdvižení, homogenní 1 se doplní. Souřadnice oddělujte čárkami, body znakem &apos;;&apos;.</translation>
    </message>
    <message>
        <source>Lifted:</source>
        <translation type="vanished">Zdvižené:</translation>
    </message>
    <message>
        <source>The start set was refused.</source>
        <translation type="vanished">Počáteční množina byla odmítnuta.</translation>
    </message>
    <message>
        <source>The item has no control points.</source>
        <translation type="vanished">Položka nemá žádné řídicí body.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number.</source>
        <translation type="vanished">„%1“ není číslo.</translation>
    </message>
    <message>
        <source>Algorithm</source>
        <translation type="vanished">Algoritmus</translation>
    </message>
    <message>
        <source>Deterministic</source>
        <translation type="vanished">Deterministický</translation>
    </message>
    <message>
        <source>Random (chaos game)</source>
        <translation type="vanished">Náhodný (hra chaosu)</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation type="vanished">Režim:</translation>
    </message>
    <message>
        <source>Depth:</source>
        <translation type="vanished">Hloubka:</translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation type="vanished">Vzorky:</translation>
    </message>
    <message>
        <source>Style</source>
        <translation type="vanished">Styl</translation>
    </message>
    <message>
        <source>By map</source>
        <translation type="vanished">Podle zobrazení</translation>
    </message>
    <message>
        <source>By address prefix</source>
        <translation type="vanished">Podle prefixu adresy</translation>
    </message>
    <message>
        <source>Single colour</source>
        <translation type="vanished">Jedna barva</translation>
    </message>
    <message>
        <source>Colour:</source>
        <translation type="vanished">Barva:</translation>
    </message>
    <message>
        <source>Prefix length:</source>
        <translation type="vanished">Délka prefixu:</translation>
    </message>
    <message>
        <source>Point size:</source>
        <translation type="vanished">Velikost bodu:</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Řídicí body</translation>
    </message>
    <message>
        <source>Set %1 (%2)</source>
        <translation>Sada %1 (%2)</translation>
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
        <translation>„%1“ není konečné číslo.</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Přidat</translation>
    </message>
    <message>
        <source>Append a point after the last one</source>
        <translation>Přidá bod za poslední bod</translation>
    </message>
    <message>
        <source>Insert</source>
        <translation>Vložit</translation>
    </message>
    <message>
        <source>Insert a point before the selected one (halfway to its predecessor)</source>
        <translation>Vloží bod před vybraný bod (v polovině cesty k předchozímu)</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Smazat</translation>
    </message>
    <message>
        <source>Delete the selected points (one undo step)</source>
        <translation>Odstraní vybrané body (jedním krokem zpět)</translation>
    </message>
    <message>
        <source>The colour of each map&apos;s points: click to choose</source>
        <translation>Barva bodů jednotlivých zobrazení: kliknutím ji zvolíte</translation>
    </message>
    <message>
        <source>Default…</source>
        <translation>Výchozí…</translation>
    </message>
    <message>
        <source>Own…</source>
        <translation>Vlastní…</translation>
    </message>
    <message>
        <source>Map colours:</source>
        <translation>Barvy zobrazení:</translation>
    </message>
    <message>
        <source>Eigenvalues</source>
        <translation type="vanished">Vlastní čísla</translation>
    </message>
    <message>
        <source>The item whose matrices are analysed</source>
        <translation type="vanished">Položka, jejíž matice se analyzují</translation>
    </message>
    <message>
        <source>S_i: the subdivision matrices (their eigenvalue 1 is affine invariance); A_i: the linear parts of the lifted maps, whose subdominant eigenvalue decides the tangents; M_i: the lifted maps themselves (003 §4, 004 §2.1)</source>
        <translation type="vanished">S_i: subdivizní matice (jejich vlastní číslo 1 vyjadřuje afinní invarianci); A_i: lineární části zdvižených zobrazení, jejichž subdominantní vlastní číslo určuje tečny; M_i: samotná zdvižená zobrazení (003 §4, 004 §2.1)</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation type="vanished">Zdroj:</translation>
    </message>
    <message>
        <source>Matrices:</source>
        <translation type="vanished">Matice:</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="vanished">(žádná)</translation>
    </message>
    <message>
        <source>%1 (missing)</source>
        <translation type="vanished">%1 (chybí)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation type="vanished">Hloubka</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation type="vanished">Vzorky</translation>
    </message>
    <message>
        <source>Prefix length</source>
        <translation type="vanished">Délka prefixu</translation>
    </message>
    <message>
        <source>Point size</source>
        <translation type="vanished">Velikost bodů</translation>
    </message>
    <message>
        <source>%1 matrices %2_i, %3 eigenvalues, plotted in the centre; click an eigenvalue to mark its map (its matrices in the Matrices dock).</source>
        <translation>%1 matic %2_i, %3 vlastních čísel, vykreslených uprostřed; kliknutím na vlastní číslo označíte jeho zobrazení (jeho matice v panelu Matice).</translation>
    </message>
    <message>
        <source>Vertex limits</source>
        <translation type="vanished">Limitní polohy vrcholů</translation>
    </message>
    <message>
        <source>Vertex limits: the exact limit positions of the mesh&apos;s vertices, where its IFS with condensation starts. Drag the control points in the 3D view; click a purple diamond to analyse that extraordinary vertex.</source>
        <translation type="vanished">Limitní polohy vrcholů: přesné limitní polohy vrcholů sítě, z nichž vychází její IFS s kondenzací. Řídicí body přetáhněte ve 3D pohledu; kliknutím na fialový kosočtverec analyzujete příslušný mimořádný vrchol.</translation>
    </message>
    <message>
        <source>For a mesh surface: the extraordinary vertex whose local subdivision matrix is analysed</source>
        <translation type="vanished">U plochy ze sítě: mimořádný vrchol, jehož lokální matice subdivize se analyzuje</translation>
    </message>
    <message>
        <source>Vertex:</source>
        <translation type="vanished">Vrchol:</translation>
    </message>
    <message>
        <source>(the mesh&apos;s matrices)</source>
        <translation type="vanished">(matice sítě)</translation>
    </message>
    <message>
        <source>vertex %1 (n = %2)</source>
        <translation type="vanished">vrchol %1 (n = %2)</translation>
    </message>
    <message>
        <source>centre of face %1 (n = %2)</source>
        <translation type="vanished">střed stěny %1 (n = %2)</translation>
    </message>
    <message>
        <source>centre of face %1 (missing)</source>
        <translation type="vanished">střed stěny %1 (chybí)</translation>
    </message>
    <message>
        <source>vertex %1 (missing)</source>
        <translation type="vanished">vrchol %1 (chybí)</translation>
    </message>
    <message>
        <source>Xforms</source>
        <translation>Xformy</translation>
    </message>
</context>
<context>
    <name>awb::PythonConsole</name>
    <message>
        <source>Python: project, item, awb (attractor_workbench) and np</source>
        <translation>Python: project, item, awb (attractor_workbench) a np</translation>
    </message>
    <message>
        <source># Python %1 console: `project` is the open document, `item` the current item, `awb` the attractor_workbench module (help(awb)). Edits are undoable; every edit made in the window is shown below as the line that makes it (Tools &gt; Save Recording).</source>
        <translation># Konzole Pythonu %1: `project` je otevřený dokument, `item` aktuální položka, `awb` modul attractor_workbench (help(awb)). Úpravy lze vrátit zpět; každá úprava provedená v okně se níže zobrazí jako řádek, který ji provede (Nástroje &gt; Uložit záznam).</translation>
    </message>
    <message>
        <source># The recording starts again, from a new project.</source>
        <translation># Záznam začíná znovu, od nového projektu.</translation>
    </message>
    <message>
        <source># The recording starts again, from %1.</source>
        <translation># Záznam začíná znovu, od %1.</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>nelze číst %1: %2</translation>
    </message>
    <message>
        <source># Running %1</source>
        <translation># Spouští se %1</translation>
    </message>
</context>
<context>
    <name>awb::Recovery</name>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1: nelze otevřít: %2</translation>
    </message>
    <message>
        <source>%1: not an Attractor Workbench recovery file</source>
        <translation>%1: není záložní soubor Attractor Workbench</translation>
    </message>
    <message>
        <source>%1: written by a newer version of Attractor Workbench</source>
        <translation>%1: zapsáno novější verzí Attractor Workbench</translation>
    </message>
    <message>
        <source>%1: field &quot;project&quot;: expected an object</source>
        <translation>%1: pole &quot;project&quot;: očekáván objekt</translation>
    </message>
</context>
<context>
    <name>awb::RegularityAtlasWindow</name>
    <message>
        <source>Regularity Atlas</source>
        <translation>Atlas regularity</translation>
    </message>
    <message>
        <source>Item:</source>
        <translation>Položka:</translation>
    </message>
    <message>
        <source>The mask with the parameters written into it, e.g. &quot;v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v&quot; (the six-point family).</source>
        <translation>Maska s vepsanými parametry, např. „v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v“ (šestibodová rodina).</translation>
    </message>
    <message>
        <source>&amp;Mask:</source>
        <translation>&amp;Maska:</translation>
    </message>
    <message>
        <source>The parameter&apos;s name: omega, a, b, or a name in the mask.</source>
        <translation>Název parametru: omega, a, b nebo název v masce.</translation>
    </message>
    <message>
        <source>Grid values, both ends included.</source>
        <translation>Hodnoty mřížky, včetně obou krajních.</translation>
    </message>
    <message>
        <source>from</source>
        <translation>od</translation>
    </message>
    <message>
        <source>to</source>
        <translation>do</translation>
    </message>
    <message>
        <source>values</source>
        <translation>hodnot</translation>
    </message>
    <message>
        <source>&amp;Second parameter:</source>
        <translation>&amp;Druhý parametr:</translation>
    </message>
    <message>
        <source>&amp;Parameter:</source>
        <translation>&amp;Parametr:</translation>
    </message>
    <message>
        <source>The class the atlas refines around: its C^k boundaries.</source>
        <translation>Třída, kolem jejíchž hranic C^k atlas zjemňuje.</translation>
    </message>
    <message>
        <source>One parameter: each boundary&apos;s bracket narrows to this width.</source>
        <translation>Jeden parametr: interval kolem každé hranice se zúží na tuto šířku.</translation>
    </message>
    <message>
        <source>Two parameters: how many times a cell whose corners disagree is split.</source>
        <translation>Dva parametry: kolikrát se rozdělí buňka, jejíž rohy se neshodují.</translation>
    </message>
    <message>
        <source>Class:</source>
        <translation>Třída:</translation>
    </message>
    <message>
        <source>Tolerance:</source>
        <translation>Tolerance:</translation>
    </message>
    <message>
        <source>Refinement levels:</source>
        <translation>Úrovně zjemnění:</translation>
    </message>
    <message>
        <source>Atlas:</source>
        <translation>Atlas:</translation>
    </message>
    <message numerus="yes">
        <source>A local Dask cluster (%n worker(s))</source>
        <translation>
            <numerusform>Místní cluster Dask (%n pracovní proces)</numerusform>
            <numerusform>Místní cluster Dask (%n pracovní procesy)</numerusform>
            <numerusform>Místní cluster Dask (%n pracovních procesů)</numerusform>
        </translation>
    </message>
    <message>
        <source>The Dask scheduler named in Preferences (none set)</source>
        <translation>Plánovač Dask zadaný v Předvolbách (není nastaven)</translation>
    </message>
    <message>
        <source>The Dask scheduler at %1</source>
        <translation>Plánovač Dask na %1</translation>
    </message>
    <message>
        <source>This machine, one process (no Dask)</source>
        <translation>Tento počítač, jeden proces (bez Dask)</translation>
    </message>
    <message>
        <source>&amp;Run on:</source>
        <translation>&amp;Spustit na:</translation>
    </message>
    <message>
        <source>&amp;Compute</source>
        <translation>&amp;Vypočítat</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>(none: select a subdivision curve)</source>
        <translation>(žádná: vyberte subdivizní křivku)</translation>
    </message>
    <message>
        <source>Write the parameters&apos; names into the mask (&quot;v, 0, w, 0, 1/2 - w - v, 1, …&quot;), give their ranges, and Compute.</source>
        <translation>Zapište názvy parametrů do masky („v, 0, w, 0, 1/2 - w - v, 1, …“), zadejte jejich rozsahy a klikněte na Vypočítat.</translation>
    </message>
    <message>
        <source>Give the parameters&apos; ranges and Compute: each point is a certified joint spectral radius, computed by python3 -m attractor_workbench.atlas.</source>
        <translation>Zadejte rozsahy parametrů a klikněte na Vypočítat: každý bod je certifikovaný společný spektrální poloměr, vypočtený pomocí python3 -m attractor_workbench.atlas.</translation>
    </message>
    <message>
        <source>Select a subdivision curve first: the atlas moves its scheme&apos;s parameters.</source>
        <translation>Nejprve vyberte subdivizní křivku: atlas mění parametry jejího schématu.</translation>
    </message>
    <message>
        <source>No Dask scheduler is set: name one in Edit &gt; Preferences, or run on a local cluster.</source>
        <translation>Není nastaven žádný plánovač Dask: zadejte jej v Úpravy &gt; Předvolby, nebo spusťte na místním clusteru.</translation>
    </message>
    <message>
        <source>Could not write the project for the atlas: %1</source>
        <translation>Projekt pro atlas nelze zapsat: %1</translation>
    </message>
    <message>
        <source>Computing in one process…</source>
        <translation>Výpočet v jednom procesu…</translation>
    </message>
    <message>
        <source>Starting the Dask cluster…</source>
        <translation>Spouštění clusteru Dask…</translation>
    </message>
    <message>
        <source>Cancelling: the cluster&apos;s tasks are being cancelled…</source>
        <translation>Rušení: úlohy clusteru se ruší…</translation>
    </message>
    <message>
        <source>Round 1: the grid&apos;s %1 points…</source>
        <translation>Kolo 1: body mřížky (%1)…</translation>
    </message>
    <message>
        <source>Round %1: %2 points where the class changes…</source>
        <translation>Kolo %1: body, kde se mění třída (%2)…</translation>
    </message>
    <message>
        <source>Round %1: %2 of %3 points; %4 in all, %5 s</source>
        <translation>Kolo %1: %2 z %3 bodů; celkem %4, %5 s</translation>
    </message>
    <message>
        <source>from %1 to %2</source>
        <translation>od %1 do %2</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s) in %1 round(s), %2 s on %3 worker(s) (%4).</source>
        <translation>
            <numerusform>%n bod, kol: %1, %2 s, pracovních procesů: %3 (%4).</numerusform>
            <numerusform>%n body, kol: %1, %2 s, pracovních procesů: %3 (%4).</numerusform>
            <numerusform>%n bodů, kol: %1, %2 s, pracovních procesů: %3 (%4).</numerusform>
        </translation>
    </message>
    <message>
        <source>Nowhere certified C^%1.</source>
        <translation>Nikde certifikovaně C^%1.</translation>
    </message>
    <message>
        <source>C^%1 %2.</source>
        <translation>C^%1 %2.</translation>
    </message>
    <message>
        <source>The atlas gave no rows.</source>
        <translation>Atlas nevrátil žádné řádky.</translation>
    </message>
    <message>
        <source>Cancelled; the points computed so far are shown.</source>
        <translation>Zrušeno; zobrazeny jsou dosud vypočtené body.</translation>
    </message>
    <message>
        <source>could not start %1: %2</source>
        <translation>nelze spustit %1: %2</translation>
    </message>
    <message>
        <source>exit code %1</source>
        <translation>návratový kód %1</translation>
    </message>
    <message>
        <source>The atlas failed: %1</source>
        <translation>Atlas selhal: %1</translation>
    </message>
    <message>
        <source>Add an item with %1</source>
        <translation>Přidat položku s %1</translation>
    </message>
    <message>
        <source>Added &quot;%1&quot; (Edit &gt; Undo removes it).</source>
        <translation>Přidána položka „%1“ (odebere ji Úpravy &gt; Zpět).</translation>
    </message>
    <message>
        <source>the scheme refuses these parameters</source>
        <translation>schéma tyto parametry odmítá</translation>
    </message>
    <message>
        <source>No item added: %1</source>
        <translation>Žádná položka nebyla přidána: %1</translation>
    </message>
</context>
<context>
    <name>awb::RegularityCertificate</name>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 není konečné číslo</translation>
    </message>
    <message>
        <source>%1 is not an index</source>
        <translation>%1 není index</translation>
    </message>
    <message>
        <source>%1 has no array &quot;%2&quot;</source>
        <translation>%1 nemá pole &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1 is not an array of numbers</source>
        <translation>%1 není pole čísel</translation>
    </message>
    <message>
        <source>&quot;polytope&quot; is not an awb-invariant-polytope object</source>
        <translation>&quot;polytope&quot; není objekt awb-invariant-polytope</translation>
    </message>
    <message>
        <source>polytope.matrices[%1] is not square</source>
        <translation>polytope.matrices[%1] není čtvercová</translation>
    </message>
    <message>
        <source>polytope.lambda[%1] holds a term that is not [index, coefficient]</source>
        <translation>polytope.lambda[%1] obsahuje člen, který nemá tvar [index, koeficient]</translation>
    </message>
    <message>
        <source>the regularity is not exact: no invariant polytope closed, so there is no certificate (%1)</source>
        <translation>regularita není přesná: žádný invariantní polytop se neuzavřel, takže certifikát neexistuje (%1)</translation>
    </message>
    <message>
        <source>not JSON: %1 at offset %2</source>
        <translation>není JSON: %1 na pozici %2</translation>
    </message>
    <message>
        <source>not an attractor-workbench regularity certificate (format %1, version 1)</source>
        <translation>není certifikát regularity attractor-workbench (formát %1, verze 1)</translation>
    </message>
    <message>
        <source>the scheme has no difference scheme to certify: %1</source>
        <translation>schéma nemá diferenční schéma, které by bylo možné certifikovat: %1</translation>
    </message>
    <message>
        <source>the certificate has %1 matrices, the scheme&apos;s analysis %2</source>
        <translation>počet matic v certifikátu: %1, v analýze schématu: %2</translation>
    </message>
    <message>
        <source>matrix %1 of the certificate is not the scheme&apos;s (the transition matrix T_%2 of its difference scheme)</source>
        <translation>matice %1 certifikátu není maticí schématu (přechodovou maticí T_%2 jeho diferenčního schématu)</translation>
    </message>
    <message>
        <source>arity %1 and shift %2 do not match the scheme&apos;s (%3 and %4)</source>
        <translation>arita %1 a posun %2 neodpovídají schématu (%3 a %4)</translation>
    </message>
    <message>
        <source>the claimed Hölder exponent [%1, %2] is not what the polytope proves: [%3, %4]</source>
        <translation>deklarovaný Hölderův exponent [%1, %2] neodpovídá tomu, co dokazuje polytop: [%3, %4]</translation>
    </message>
    <message>
        <source>certificate verified: the Hölder exponent of the %1 lies in [%2, %3]; JSR in [%4, %5]</source>
        <translation>certifikát ověřen (%1): Hölderův exponent leží v [%2, %3]; JSR v [%4, %5]</translation>
    </message>
    <message>
        <source>certificate rejected: %1</source>
        <translation>certifikát zamítnut: %1</translation>
    </message>
</context>
<context>
    <name>awb::RegularityChart</name>
    <message>
        <source>Regularity of the four-point scheme</source>
        <translation>Regularita čtyřbodového schématu</translation>
    </message>
    <message>
        <source>Certified Hölder regularity r(ω) of the four-point scheme</source>
        <translation>Ověřená Hölderovská regularita r(ω) čtyřbodového schématu</translation>
    </message>
    <message>
        <source>lower bound</source>
        <translation>dolní mez</translation>
    </message>
    <message>
        <source>upper bound</source>
        <translation>horní mez</translation>
    </message>
    <message>
        <source>known: ω = 0 → 1, ω = 1/16 → 2</source>
        <translation type="vanished">známé hodnoty: ω = 0 → 1, ω = 1/16 → 2</translation>
    </message>
    <message>
        <source>tension ω</source>
        <translation>napětí ω</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Computing %1 values of ω…</source>
        <translation>Výpočet hodnot ω (%1)…</translation>
    </message>
    <message>
        <source>%1 values of ω; widest interval %2 (bounds certified; the upper bound is exact for this interpolatory scheme)</source>
        <translation type="vanished">Hodnoty ω: %1; nejširší interval %2 (meze jsou ověřené; horní mez je pro toto interpolační schéma přesná)</translation>
    </message>
    <message>
        <source>regularity r</source>
        <translation>regularita r</translation>
    </message>
    <message>
        <source>r(0) = 1, r(1/16) = 2</source>
        <translation>r(0) = 1, r(1/16) = 2</translation>
    </message>
    <message>
        <source>C%1 (certified)</source>
        <translation>C%1 (certifikováno)</translation>
    </message>
    <message>
        <source>; C¹ for ω in (%1, %2), the ends in [%3, %4] and [%5, %6]</source>
        <translation>; C¹ pro ω v (%1, %2), konce v [%3, %4] a [%5, %6]</translation>
    </message>
    <message>
        <source>%1 values of ω; widest interval %2 (bounds certified; the upper bound is exact for this interpolatory scheme)%3</source>
        <translation>počet hodnot ω: %1; nejširší interval %2 (meze certifikovány; horní mez je pro toto interpolační schéma přesná)%3</translation>
    </message>
</context>
<context>
    <name>awb::RegularityPanel</name>
    <message>
        <source>Regularity: no curve scheme</source>
        <translation>Regularita: žádné schéma křivky</translation>
    </message>
    <message>
        <source>Regularity %p%</source>
        <translation>Regularita %p%</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Stop the regularity analysis; the bounds reached so far stay</source>
        <translation>Zastaví analýzu regularity; dosud dosažené meze zůstanou</translation>
    </message>
    <message>
        <source>Regularity of %1: computing…</source>
        <translation>Regularita položky %1: probíhá výpočet…</translation>
    </message>
    <message>
        <source>so far: r in [%1, %2]</source>
        <translation>zatím: r v [%1, %2]</translation>
    </message>
    <message>
        <source>Regularity: %1</source>
        <translation>Regularita: %1</translation>
    </message>
    <message>
        <source>Save Certificate…</source>
        <translation>Uložit certifikát…</translation>
    </message>
    <message>
        <source>The invariant polytope that proves the exponent, as JSON: attractor-cli verify-regularity re-checks it without any search</source>
        <translation>Invariantní polytop, který dokazuje exponent, ve formátu JSON: attractor-cli verify-regularity jej znovu ověří bez jakéhokoli hledání</translation>
    </message>
</context>
<context>
    <name>awb::RemoveControlPointCommand</name>
    <message>
        <source>Remove a control point of %1</source>
        <translation>Odstranit řídicí bod položky %1</translation>
    </message>
</context>
<context>
    <name>awb::RemoveItemCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>Odstranit %1</translation>
    </message>
</context>
<context>
    <name>awb::SchemeFamily</name>
    <message>
        <source>a family has one or two parameters, got %1</source>
        <translation>rodina má jeden nebo dva parametry, zadáno: %1</translation>
    </message>
    <message>
        <source>the two parameters have the same name &apos;%1&apos;</source>
        <translation>oba parametry mají stejný název „%1“</translation>
    </message>
    <message>
        <source>a mask with parameters needs a mask item; this one is %1</source>
        <translation>maska s parametry vyžaduje položku typu maska; tato je %1</translation>
    </message>
    <message>
        <source>the parameter of a mask must be a name that is not a function or constant (pi, e, sqrt, ...), got &apos;%1&apos;</source>
        <translation>parametrem masky musí být název, který není funkcí ani konstantou (pi, e, sqrt, ...), zadáno: „%1“</translation>
    </message>
    <message>
        <source>the mask &apos;%1&apos; does not contain the parameter &apos;%2&apos;</source>
        <translation>maska „%1“ neobsahuje parametr „%2“</translation>
    </message>
    <message>
        <source>the scheme (%1) has no parameter &apos;%2&apos;: omega belongs to the four-point scheme, a and b to corner cutting; a mask item takes a mask with the parameter in its coefficients</source>
        <translation>schéma (%1) nemá parametr „%2“: omega patří ke čtyřbodovému schématu, a a b k ořezávání rohů; položka typu maska přijímá masku s parametrem v koeficientech</translation>
    </message>
    <message>
        <source>expected %1 parameter values, got %2</source>
        <translation>očekávaný počet hodnot parametrů: %1, zadáno: %2</translation>
    </message>
    <message>
        <source>expected a list of names</source>
        <translation>očekáván seznam názvů</translation>
    </message>
    <message>
        <source>family: %1: %2</source>
        <translation>rodina: %1: %2</translation>
    </message>
    <message>
        <source>an atlas row has no value of &apos;%1&apos;</source>
        <translation>řádek atlasu nemá hodnotu „%1“</translation>
    </message>
</context>
<context>
    <name>awb::SchemeRegularity</name>
    <message>
        <source>does not apply: a complex de Casteljau parameter is not a real subdivision scheme</source>
        <translation>nelze použít: komplexní de Casteljauův parametr nedává reálné subdivizní schéma</translation>
    </message>
    <message>
        <source>does not apply: %1</source>
        <translation>nelze použít: %1</translation>
    </message>
</context>
<context>
    <name>awb::ScriptRecorder</name>
    <message>
        <source>Undo</source>
        <translation>Zpět</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Znovu</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Úprava</translation>
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
        <translation>jednotková kružnice</translation>
    </message>
    <message>
        <source>dominant 1</source>
        <translation>dominantní 1</translation>
    </message>
    <message>
        <source>subdominant</source>
        <translation>subdominantní</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: λ = %2, |λ| = %3, multiplicity %4, arg λ = %6° (map %5)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: λ = %2, |λ| = %3, násobnost %4, arg λ = %6° (zobrazení %5)</translation>
    </message>
    <message>
        <source> — dominant</source>
        <translation> — dominantní</translation>
    </message>
    <message>
        <source> — subdominant</source>
        <translation> — subdominantní</translation>
    </message>
    <message>
        <source>&lt;p&gt;No maps.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Žádná zobrazení.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;All maps are (eventually) contractive&lt;/b&gt;: the IFS has a unique attractor.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Všechna zobrazení jsou (eventuálně) kontraktivní&lt;/b&gt;: IFS má jediný atraktor.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;%1 is not contractive&lt;/b&gt;: the IFS has no attractor and its iteration does not converge.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;%1 není kontraktivní&lt;/b&gt;: IFS nemá atraktor a jeho iterace nekonverguje.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Not contractive: spectral radius %1 ≥ 1.</source>
        <translation>Není kontraktivní: spektrální poloměr %1 ≥ 1.</translation>
    </message>
    <message>
        <source>Contractive: ‖A‖&lt;sub&gt;2&lt;/sub&gt; = %1 &amp;lt; 1.</source>
        <translation>Kontraktivní: ‖A‖&lt;sub&gt;2&lt;/sub&gt; = %1 &amp;lt; 1.</translation>
    </message>
    <message>
        <source>Eventually contractive: spectral radius %1 &amp;lt; 1, ‖A&lt;sup&gt;%2&lt;/sup&gt;‖&lt;sub&gt;2&lt;/sub&gt; &amp;lt; 1.</source>
        <translation>Eventuálně kontraktivní: spektrální poloměr %1 &amp;lt; 1, ‖A&lt;sup&gt;%2&lt;/sup&gt;‖&lt;sub&gt;2&lt;/sub&gt; &amp;lt; 1.</translation>
    </message>
    <message>
        <source>Eventually contractive: spectral radius %1 &amp;lt; 1.</source>
        <translation>Eventuálně kontraktivní: spektrální poloměr %1 &amp;lt; 1.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>žádné</translation>
    </message>
    <message>
        <source>No subdominant eigenvalue: the map is constant.</source>
        <translation>Žádné subdominantní vlastní číslo: zobrazení je konstantní.</translation>
    </message>
    <message>
        <source>real positive</source>
        <translation>reálné kladné</translation>
    </message>
    <message>
        <source>The curve has a half-tangent at the fixed point, along the eigenvector (G¹ where the two sides&apos; eigenvectors align).</source>
        <translation>Křivka má v pevném bodě polotečnu ve směru vlastního vektoru (G¹ tam, kde jsou vlastní vektory obou stran souhlasně rovnoběžné).</translation>
    </message>
    <message>
        <source>Repeated: the tangent direction at the fixed point depends on the control points.</source>
        <translation>Násobné: směr tečny v pevném bodě závisí na řídicích bodech.</translation>
    </message>
    <message>
        <source>real negative</source>
        <translation>reálné záporné</translation>
    </message>
    <message>
        <source>The curve oscillates at the fixed point and has no tangent there.</source>
        <translation>Křivka v pevném bodě osciluje a nemá v něm tečnu.</translation>
    </message>
    <message>
        <source>complex pair</source>
        <translation>komplexně sdružená dvojice</translation>
    </message>
    <message>
        <source>The curve spirals around the fixed point (no tangent).</source>
        <translation>Křivka se kolem pevného bodu stáčí do spirály (bez tečny).</translation>
    </message>
    <message>
        <source>complex</source>
        <translation>komplexní</translation>
    </message>
    <message>
        <source>Near the fixed point the map acts as the spiral similarity z ↦ λz: the curve spirals around the fixed point (no tangent).</source>
        <translation>V blízkosti pevného bodu působí zobrazení jako spirální podobnost z ↦ λz: křivka se kolem pevného bodu stáčí do spirály (bez tečny).</translation>
    </message>
    <message>
        <source>mixed</source>
        <translation>smíšené</translation>
    </message>
    <message>
        <source>Several eigenvalues of the same modulus with different signs or phases: no single tangent behaviour.</source>
        <translation>Několik vlastních čísel se stejným modulem, ale různými znaménky nebo fázemi: žádné jednotné chování tečny.</translation>
    </message>
    <message>
        <source>Subdominant: none.</source>
        <translation>Subdominantní: žádné.</translation>
    </message>
    <message>
        <source>Subdominant: %1 (%2, |λ| = %3, multiplicity %4).</source>
        <translation>Subdominantní: %1 (%2, |λ| = %3, násobnost %4).</translation>
    </message>
    <message>
        <source>Unknown file type “%1”: use .pdf, .svg or .png.</source>
        <translation>Neznámý typ souboru „%1“: použijte .pdf, .svg nebo .png.</translation>
    </message>
    <message>
        <source>Eigenvalues</source>
        <translation>Vlastní čísla</translation>
    </message>
    <message>
        <source>%1: λ = %2</source>
        <translation>%1: λ = %2</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;%1 is not contractive, but the IFS contracts on average&lt;/b&gt;: its Lyapunov exponent is %2 &amp;lt; 0 (Barnsley–Elton), so random iteration converges to its attractor, as in flame renderers; deterministic iteration does not.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;%1 není kontraktivní, ale IFS je kontraktivní v průměru&lt;/b&gt;: jeho Ljapunovův exponent je %2 &amp;lt; 0 (Barnsley–Elton), takže náhodná iterace konverguje k jeho atraktoru jako v programech pro fraktální plameny; deterministická iterace nekonverguje.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>The spectra below are those of the xforms&apos; affine (pre) maps; the variations bend the maps, so the spectra alone say nothing of the flame&apos;s attractor.</source>
        <translation>Spektra níže patří afinním (pre) částem xformů; variace zobrazení ohýbají, takže samotná spektra o atraktoru plamene nic neříkají.</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;The flame contracts on average&lt;/b&gt;: the top Lyapunov exponent of its chaos game along its own orbit is %1 &amp;lt; 0, so the game converges to its attractor. %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Plamen se v průměru zmenšuje&lt;/b&gt;: největší Ljapunovův exponent jeho hry chaosu podél jeho vlastní orbity je %1 &amp;lt; 0, takže hra konverguje k jeho atraktoru. %2&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;The flame does not contract on average&lt;/b&gt;: the top Lyapunov exponent of its chaos game along its own orbit is %1 &amp;ge; 0, so its picture is not an attractor&apos;s. %2&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;Plamen se v průměru nezmenšuje&lt;/b&gt;: největší Ljapunovův exponent jeho hry chaosu podél jeho vlastní orbity je %1 &amp;ge; 0, takže jeho obraz není obrazem atraktoru. %2&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>awb::StartSetSpec</name>
    <message>
        <source>a lifted start set needs at least one point</source>
        <translation>zdvižená počáteční množina vyžaduje alespoň jeden bod</translation>
    </message>
    <message>
        <source>lifted start point %1 has %2 coordinates: every point needs the same number, at least 2</source>
        <translation>zdvižený počáteční bod %1 má počet souřadnic %2: všechny body musí mít stejný počet, alespoň 2</translation>
    </message>
    <message>
        <source>every point must have finite coordinates</source>
        <translation>všechny body musí mít konečné souřadnice</translation>
    </message>
    <message>
        <source>a start set of kind &quot;%1&quot; needs exactly %2 points, got %3</source>
        <translation>počáteční množina druhu „%1“: počet bodů musí být přesně %2, zadáno %3</translation>
    </message>
    <message>
        <source>a start set of kind &quot;%1&quot; needs at least %2 points, got %3</source>
        <translation>počáteční množina druhu „%1“: počet bodů musí být alespoň %2, zadáno %3</translation>
    </message>
    <message>
        <source>a start set of net points needs at least one index</source>
        <translation>počáteční množina z bodů sítě potřebuje alespoň jeden index</translation>
    </message>
    <message>
        <source>a start set of net points takes at most %1 indices, got %2</source>
        <translation>počáteční množina z bodů sítě smí mít nejvýše %1 indexů, zadáno %2</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2: indices count from 0</source>
        <translation>bod sítě %1 počáteční množiny má index %2: indexy se počítají od 0</translation>
    </message>
</context>
<context>
    <name>awb::StartSetText</name>
    <message>
        <source>&apos;%1&apos; is not a finite number</source>
        <translation>„%1“ není konečné číslo</translation>
    </message>
    <message>
        <source>a start set is written point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | vertex-limits, got &apos;%1&apos;</source>
        <translation type="vanished">počáteční množina se zapisuje point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | vertex-limits, zadáno „%1“</translation>
    </message>
    <message>
        <source>a %1 needs %2 coordinates (%3 per point), got %4</source>
        <translation>%1 potřebuje %2 souřadnic (%3 na bod), zadáno %4</translation>
    </message>
    <message>
        <source>a multiple of %1</source>
        <translation>násobek %1</translation>
    </message>
    <message>
        <source>lifted: needs at least one point</source>
        <translation>lifted: potřebuje alespoň jeden bod</translation>
    </message>
    <message>
        <source>vertex-limits needs a mesh item; &apos;%1&apos; is a %2</source>
        <translation>vertex-limits potřebuje položku sítě; „%1“ je %2</translation>
    </message>
    <message>
        <source>a start set is written point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | net:i,j,... | vertex-limits, got &apos;%1&apos;</source>
        <translation>počáteční množina se zapisuje point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | net:i,j,... | vertex-limits, zadáno „%1“</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a net point index (an integer from 0)</source>
        <translation>„%1“ není index bodu sítě (celé číslo od 0)</translation>
    </message>
    <message>
        <source>net: needs at least one index</source>
        <translation>net: potřebuje alespoň jeden index</translation>
    </message>
</context>
<context>
    <name>awb::StyleSpec</name>
    <message>
        <source>the density gamma must be between 0.2 and 10, got %1</source>
        <translation>gama hustoty musí být mezi 0.2 a 10, zadáno %1</translation>
    </message>
    <message>
        <source>the address prefix length must be between 1 and %1, got %2</source>
        <translation>délka prefixu adresy musí být mezi 1 a %1, zadáno %2</translation>
    </message>
    <message>
        <source>the point size must be more than 0 and at most %1 pixels</source>
        <translation>velikost bodu musí být větší než 0 a nejvýše %1 pixelů</translation>
    </message>
    <message>
        <source>colour %1 is &quot;%2&quot;, expected &quot;#rrggbb&quot; (lower-case hexadecimal)</source>
        <translation>barva %1 je „%2“, očekáváno &quot;#rrggbb&quot; (šestnáctkově, malými písmeny)</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionCurveItem</name>
    <message>
        <source>Bézier of degree %1 needs exactly %2 control points, got %3</source>
        <translation>Bézierova křivka stupně %1: počet řídicích bodů musí být přesně %2, zadáno %3</translation>
    </message>
    <message>
        <source>a complex Bézier parameter has no real scheme</source>
        <translation>komplexní Bézierův parametr nemá reálné schéma</translation>
    </message>
    <message>
        <source>unknown scheme kind</source>
        <translation>neznámý druh schématu</translation>
    </message>
    <message>
        <source>the complex parameter t = %1 %2 %3i must satisfy |t| &lt; 1 and |1 - t| &lt; 1 (004 §3.7)</source>
        <translation>komplexní parametr t = %1 %2 %3i musí splňovat |t| &lt; 1 a |1 - t| &lt; 1 (004 §3.7)</translation>
    </message>
    <message>
        <source>Curve</source>
        <translation>Křivka</translation>
    </message>
    <message>
        <source>Change scheme of %1</source>
        <translation>Změnit schéma položky %1</translation>
    </message>
    <message>
        <source>expected [re, im] or a number</source>
        <translation>očekáváno [re, im] nebo číslo</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Uniform B-spline</source>
        <translation>Uniformní B-spline</translation>
    </message>
    <message>
        <source>End-interpolating B-spline</source>
        <translation>B-spline interpolující koncové body</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Corner cutting</source>
        <translation>Ořezávání rohů</translation>
    </message>
    <message>
        <source>Four-point</source>
        <translation>Čtyřbodové</translation>
    </message>
    <message>
        <source>Bézier (de Casteljau)</source>
        <translation>Bézierovo (de Casteljau)</translation>
    </message>
    <message>
        <source>Own matrices</source>
        <translation>Vlastní matice</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Stupeň</translation>
    </message>
    <message>
        <source>Degree n: the curve has n + 1 control points</source>
        <translation>Stupeň n: křivka má n + 1 řídicích bodů</translation>
    </message>
    <message>
        <source>Degree of the B-spline (Lane–Riesenfeld, 004 eq. 2.7)</source>
        <translation>Stupeň B-spline (Lane–Riesenfeld, 004 eq. 2.7)</translation>
    </message>
    <message>
        <source>Split parameter t</source>
        <translation>Parametr dělení t</translation>
    </message>
    <message>
        <source>de Casteljau split at t (004 eq. 2.5). A complex t inside both discs |t| &lt; 1, |1 − t| &lt; 1 gives a fractal curve (004 §3.7).</source>
        <translation>de Casteljauovo dělení v bodě t (004 eq. 2.5). Komplexní t uvnitř obou kruhů |t| &lt; 1, |1 − t| &lt; 1 dává fraktální křivku (004 §3.7).</translation>
    </message>
    <message>
        <source>Tension ω</source>
        <translation>Napětí ω</translation>
    </message>
    <message>
        <source>1/16 gives C1 curves reproducing cubics; −1/2 &lt; ω &lt; 0 or 1/4 ≤ ω &lt; 1/2 gives fractal curves (004 Thm. 2.4.1)</source>
        <translation>1/16 dává C1 křivky reprodukující kubiky; −1/2 &lt; ω &lt; 0 nebo 1/4 ≤ ω &lt; 1/2 dává fraktální křivky (004 Thm. 2.4.1)</translation>
    </message>
    <message>
        <source>New points at parameters a &lt; b on every edge (Chaikin: 1/4, 3/4)</source>
        <translation>Nové body v parametrech a &lt; b na každé hraně (Chaikin: 1/4, 3/4)</translation>
    </message>
    <message>
        <source>First cut a</source>
        <translation>První řez a</translation>
    </message>
    <message>
        <source>Second cut b</source>
        <translation>Druhý řez b</translation>
    </message>
    <message>
        <source>Subdivision curve</source>
        <translation>Subdivizní křivka</translation>
    </message>
    <message>
        <source>mask entry %1, &quot;%2&quot;, is not a number (fractions such as 3/8 and expressions such as (1 + sqrt(3))/8 are)</source>
        <translation>položka masky %1, &quot;%2&quot;, není číslo (čísly jsou zlomky jako 3/8 a výrazy jako (1 + sqrt(3))/8)</translation>
    </message>
    <message>
        <source>no sum rule: σ(z) = %1 does not divide the symbol a(z), so the scheme has no difference scheme and cannot converge</source>
        <translation>žádné součtové pravidlo: σ(z) = %1 nedělí symbol a(z), takže schéma nemá diferenční schéma a nemůže konvergovat</translation>
    </message>
    <message>
        <source>1 sum rule</source>
        <translation>1 součtové pravidlo</translation>
    </message>
    <message>
        <source>%1 sum rules</source>
        <translation>počet součtových pravidel: %1</translation>
    </message>
    <message>
        <source>%1: a(z) = σ(z)%2 b(z) / %3%2 with σ(z) = %4 and b = (%5) from z%6</source>
        <translation>%1 – a(z) = σ(z)%2 b(z) / %3%2, kde σ(z) = %4 a b = (%5) od z%6</translation>
    </message>
    <message>
        <source>expected a non-empty array of coefficients</source>
        <translation>očekáváno neprázdné pole koeficientů</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>Maska</translation>
    </message>
    <message>
        <source>Arity N</source>
        <translation>Arita N</translation>
    </message>
    <message>
        <source>Each step makes N new points per old one. A new arity whose cosets the mask does not fit starts from the N-ary piecewise linear mask.</source>
        <translation>Každý krok vytvoří z každého starého bodu N nových. Pokud maska neodpovídá zbytkovým třídám nové arity, začne se od N-ární po částech lineární masky.</translation>
    </message>
    <message>
        <source>Mask a_k</source>
        <translation>Maska a_k</translation>
    </message>
    <message>
        <source>q_n = Σ a_(n − N l) p_l. Separate the coefficients by commas (by semicolons to use decimal commas); fractions (3/8) and expressions ((1 + sqrt(3))/8) are kept as typed. Each of the N cosets a_(r + N k) must sum to 1.</source>
        <translation>q_n = Σ a_(n − N l) p_l. Koeficienty oddělujte čárkami (středníky, chcete-li používat desetinné čárky); zlomky (3/8) a výrazy ((1 + sqrt(3))/8) se zachovají tak, jak jsou zapsány. Každá z N zbytkových tříd a_(r + N k) musí mít součet 1.</translation>
    </message>
    <message>
        <source>First index k</source>
        <translation>První index k</translation>
    </message>
    <message>
        <source>The index of the mask&apos;s first coefficient: the cubic B-spline is 1/8, 1/2, 3/4, 1/2, 1/8 from k = −2</source>
        <translation>Index prvního koeficientu masky: kubický B-spline je 1/8, 1/2, 3/4, 1/2, 1/8 od k = −2</translation>
    </message>
    <message>
        <source>Symbol</source>
        <translation>Symbol</translation>
    </message>
    <message>
        <source>The symbol a(z) = Σ a_k z^k divided by σ(z) = 1 + z + … + z^(N−1) as often as it goes: each factor is one sum rule (polynomials of one more degree reproduced, one more difference scheme)</source>
        <translation>Symbol a(z) = Σ a_k z^k vydělený σ(z) = 1 + z + … + z^(N−1) tolikrát, kolikrát to jde: každý faktor je jedno součtové pravidlo (reprodukují se polynomy o stupeň vyšší, přibude jedno diferenční schéma)</translation>
    </message>
    <message>
        <source>the symbol follows from the mask: edit the mask</source>
        <translation type="vanished">symbol vyplývá z masky: upravte masku</translation>
    </message>
    <message>
        <source>Matrices S_i</source>
        <translation>Matice S_i</translation>
    </message>
    <message>
        <source>The subdivision matrices S_1 .. S_p, m x m with rows summing to 1; edited cell by cell in the Matrices dock</source>
        <translation>Subdivizní matice S_1 .. S_p, rozměru m x m, součet každého řádku je 1; upravují se buňku po buňce v panelu Matice</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Řídicí body</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionMeshItem</name>
    <message>
        <source>Mesh surface</source>
        <translation>Plocha ze sítě</translation>
    </message>
    <message>
        <source>Change mesh of %1</source>
        <translation>Změnit síť položky %1</translation>
    </message>
    <message>
        <source>a mesh surface is drawn by deterministic iteration: random iteration of its pieces is not implemented</source>
        <translation>plocha ze sítě se kreslí deterministickou iterací: náhodná iterace jejích částí není implementována</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after %3 isolating steps (docs/mathematics.md, &quot;Extraordinary vertices&quot;)</source>
        <translation type="vanished">%1 částí %2 druhů po %3 izolačních krocích (docs/mathematics.md, &quot;Extraordinary vertices&quot;)</translation>
    </message>
    <message>
        <source>expected an array of faces, each an array of vertex numbers</source>
        <translation>očekáváno pole stěn, každá jako pole čísel vrcholů</translation>
    </message>
    <message>
        <source>expected a face: an array of vertex numbers (0-based)</source>
        <translation>očekávána stěna: pole čísel vrcholů (číslovaných od 0)</translation>
    </message>
    <message>
        <source>vertex numbers are whole numbers (0-based)</source>
        <translation>čísla vrcholů jsou celá čísla (číslovaná od 0)</translation>
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
        <translation>Loop přijímá jen trojúhelníkové sítě</translation>
    </message>
    <message>
        <source>Colours</source>
        <translation type="vanished">Barvy</translation>
    </message>
    <message>
        <source>By map</source>
        <translation>Podle zobrazení</translation>
    </message>
    <message>
        <source>By level around extraordinary vertices</source>
        <translation>Podle úrovně kolem mimořádných vrcholů</translation>
    </message>
    <message>
        <source>Style</source>
        <translation>Styl</translation>
    </message>
    <message>
        <source>a mesh has no single lifted space: each of its pieces is lifted over its own control net</source>
        <translation>síť nemá jediný zdvižený prostor: každá její část se zdvihá nad svou vlastní řídicí sítí</translation>
    </message>
    <message>
        <source>By level: around an extraordinary vertex, the rings C, f(C), f²(C), … of its IFS with condensation get colours in turn</source>
        <translation>Podle úrovně: kolem mimořádného vrcholu dostávají prstence C, f(C), f²(C), … jeho IFS s kondenzací postupně barvy</translation>
    </message>
    <message>
        <source>the steps before the limit positions must be 0 to %1, got %2</source>
        <translation>počet kroků před limitními polohami musí být 0 až %1, je %2</translation>
    </message>
    <message>
        <source>%1 steps give about %2 vertices: more than %3</source>
        <translation>počet kroků %1 dá přibližně %2 vrcholů: více než %3</translation>
    </message>
    <message>
        <source>Attractor Workbench: item %1, %2 after %3 steps, every vertex at its limit position</source>
        <translation>Attractor Workbench: položka %1, %2 po %3 krocích, každý vrchol v limitní poloze</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Vrcholy</translation>
    </message>
    <message>
        <source>The mesh&apos;s vertices [x, y, z]: its control points</source>
        <translation>Vrcholy sítě [x, y, z]: její řídicí body</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>Stěny</translation>
    </message>
    <message>
        <source>Each face as the loop of its vertex numbers (0-based)</source>
        <translation>Každá stěna jako cyklus čísel jejích vrcholů (číslovaných od 0)</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after %3 steps that isolate the extraordinary vertices</source>
        <translation>Počet částí %1, počet druhů %2, počet kroků izolujících mimořádné vrcholy %3</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after one step that isolates the extraordinary vertices</source>
        <translation>Počet částí %1, počet druhů %2 po jednom kroku izolujícím mimořádné vrcholy</translation>
    </message>
    <message>
        <source>Pieces coloured</source>
        <translation>Obarvení částí</translation>
    </message>
    <message>
        <source>expected an array, each entry %1</source>
        <translation>očekáváno pole, v němž je každá položka %1</translation>
    </message>
    <message>
        <source>expected %1</source>
        <translation>očekáváno: %1</translation>
    </message>
    <message>
        <source>vertex and face numbers are whole numbers (0-based)</source>
        <translation>čísla vrcholů a stěn jsou celá čísla (číslovaná od 0)</translation>
    </message>
    <message>
        <source>a sharpness is a number of 0 or more (10 or more: infinitely sharp)</source>
        <translation>ostrost je číslo 0 nebo větší (10 a více: nekonečně ostré)</translation>
    </message>
    <message>
        <source>a crease: [first vertex, second vertex, sharpness]</source>
        <translation>ostrá hrana ve tvaru [první vrchol, druhý vrchol, ostrost]</translation>
    </message>
    <message>
        <source>Creases</source>
        <translation>Ostré hrany</translation>
    </message>
    <message>
        <source>Sharp features</source>
        <translation>Ostré prvky</translation>
    </message>
    <message>
        <source>Sharp edges as [first vertex, second vertex, sharpness]: sharp for that many levels (10 or more: for ever), as OpenSubdiv&apos;s creases</source>
        <translation>Ostré hrany ve tvaru [první vrchol, druhý vrchol, ostrost]: zůstávají ostré po daný počet úrovní dělení (10 a více: navždy), jako ostré hrany (creases) v OpenSubdiv</translation>
    </message>
    <message>
        <source>a corner: [vertex, sharpness]</source>
        <translation>roh ve tvaru [vrchol, ostrost]</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Rohy</translation>
    </message>
    <message>
        <source>Sharp vertices as [vertex, sharpness]: the surface passes through them while the sharpness lasts</source>
        <translation>Ostré vrcholy ve tvaru [vrchol, ostrost]: plocha jimi prochází, dokud jejich ostrost trvá</translation>
    </message>
    <message>
        <source>a face number (0-based)</source>
        <translation>číslo stěny (číslováno od 0)</translation>
    </message>
    <message>
        <source>Holes</source>
        <translation>Díry</translation>
    </message>
    <message>
        <source>Faces (0-based) left out of the surface; they still shape their neighbours</source>
        <translation>Stěny (číslované od 0) vynechané z plochy; tvar sousedních stěn přesto dál ovlivňují</translation>
    </message>
    <message>
        <source>None (faces at the boundary are left out)</source>
        <translation>Žádná (stěny na hranici se vynechají)</translation>
    </message>
    <message>
        <source>Edges</source>
        <translation>Hrany</translation>
    </message>
    <message>
        <source>Edges and corners</source>
        <translation>Hrany a rohy</translation>
    </message>
    <message>
        <source>Boundary</source>
        <translation>Hranice</translation>
    </message>
    <message>
        <source>How the boundary is interpolated (OpenSubdiv&apos;s VtxBoundaryInterpolation): with corners, a vertex of one face is a corner of the surface</source>
        <translation>Jak se interpoluje hranice (VtxBoundaryInterpolation v OpenSubdiv): s rohy se vrchol, který patří jen jedné stěně, stává rohem plochy</translation>
    </message>
    <message>
        <source>Uniform</source>
        <translation>Rovnoměrná</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Crease method</source>
        <translation>Metoda ostrých hran</translation>
    </message>
    <message>
        <source>How a semi-sharp crease decays: by 1 per level, or Chaikin&apos;s average with its neighbours</source>
        <translation>Jak ubývá ostrost poloostré hrany: o 1 na každé úrovni, nebo Chaikinovým průměrováním se sousedními hranami</translation>
    </message>
    <message>
        <source>Smooth triangles</source>
        <translation>Hladké trojúhelníky</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Trojúhelníky</translation>
    </message>
    <message>
        <source>Catmull–Clark&apos;s edge points next to triangles: as for any face, or OpenSubdiv&apos;s smoother weights</source>
        <translation>Hranové body schématu Catmull–Clark vedle trojúhelníků: stejně jako u kterékoli jiné stěny, nebo s hladšími vahami z OpenSubdiv</translation>
    </message>
    <message>
        <source>face %1: the mesh has %2 faces (0 to %3)</source>
        <translation>stěna %1: síť má %2 stěn (0 až %3)</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionSurfaceItem</name>
    <message>
        <source>Surface</source>
        <translation>Plocha</translation>
    </message>
    <message>
        <source>Change net of %1</source>
        <translation>Změnit síť položky %1</translation>
    </message>
    <message>
        <source>Change subdivision rounds of %1</source>
        <translation>Změnit kola subdivize položky %1</translation>
    </message>
    <message>
        <source>Turn the view of %1</source>
        <translation>Otočit pohled položky %1</translation>
    </message>
    <message>
        <source>expected an array of lattice coordinates [i, j]</source>
        <translation>očekáváno pole mřížových souřadnic [i, j]</translation>
    </message>
    <message>
        <source>expected lattice coordinates [i, j]</source>
        <translation>očekávány mřížové souřadnice [i, j]</translation>
    </message>
    <message>
        <source>lattice coordinates are whole numbers</source>
        <translation>mřížové souřadnice jsou celá čísla</translation>
    </message>
    <message>
        <source>at least one map must be used (leave the field out to use all)</source>
        <translation>musí být použito alespoň jedno zobrazení (pro použití všech pole vynechte)</translation>
    </message>
    <message>
        <source>map indices are whole numbers (0-based)</source>
        <translation>indexy zobrazení jsou celá čísla (číslovaná od 0)</translation>
    </message>
    <message>
        <source>the elevation must be from -90 to 90 degrees</source>
        <translation>elevace musí být od -90 do 90 stupňů</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <source>Bicubic B-spline (Catmull–Clark)</source>
        <translation>Bikubický B-spline (Catmull–Clark)</translation>
    </message>
    <message>
        <source>Loop (three-direction box spline)</source>
        <translation>Loop (třísměrový box spline)</translation>
    </message>
    <message>
        <source>Kobbelt √3</source>
        <translation>Kobbelt √3</translation>
    </message>
    <message>
        <source>A new scheme starts from its own default net (000 §3)</source>
        <translation>Nové schéma začíná z vlastní výchozí sítě (000 §3)</translation>
    </message>
    <message>
        <source>Layout</source>
        <translation>Rozložení</translation>
    </message>
    <message>
        <source>The patch&apos;s domain and the maps covering it</source>
        <translation>Definiční obor plátu a zobrazení, která jej pokrývají</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>Zobrazení</translation>
    </message>
    <message>
        <source>Map %1</source>
        <translation>Zobrazení %1</translation>
    </message>
    <message>
        <source>Leave maps out to draw a fractal lying on the surface (000 Fig. 9)</source>
        <translation>Vynecháním zobrazení nakreslíte fraktál ležící na ploše (000 Fig. 9)</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Pohled</translation>
    </message>
    <message>
        <source>Azimuth</source>
        <translation>Azimut</translation>
    </message>
    <message>
        <source>Direction of the orthographic camera around the z axis, in degrees</source>
        <translation>Směr ortografické kamery kolem osy z, ve stupních</translation>
    </message>
    <message>
        <source>Elevation</source>
        <translation>Elevace</translation>
    </message>
    <message>
        <source>Height of the camera above the xy plane, in degrees</source>
        <translation>Výška kamery nad rovinou xy, ve stupních</translation>
    </message>
    <message>
        <source>Subdivision rounds</source>
        <translation>Kola subdivize</translation>
    </message>
    <message>
        <source>Rounds of classic subdivision of the net (000 Figs. 6–8, top)</source>
        <translation>Kola klasické subdivize sítě (000 Figs. 6–8, nahoře)</translation>
    </message>
    <message>
        <source>from 0 to %1 rounds</source>
        <translation>od 0 do %1 kol</translation>
    </message>
    <message>
        <source>at least one map must stay on</source>
        <translation>alespoň jedno zobrazení musí zůstat zapnuté</translation>
    </message>
    <message>
        <source>Subdivision surface</source>
        <translation>Subdivizní plocha</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Řídicí body</translation>
    </message>
    <message>
        <source>Lattice coordinates</source>
        <translation>Mřížové souřadnice</translation>
    </message>
    <message>
        <source>Each control point&apos;s place [i, j] on the scheme&apos;s lattice</source>
        <translation>Poloha [i, j] každého řídicího bodu na mříži schématu</translation>
    </message>
    <message>
        <source>Maps used</source>
        <translation>Použitá zobrazení</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceNet</name>
    <message>
        <source>every control point must have finite coordinates</source>
        <translation>každý řídicí bod musí mít konečné souřadnice</translation>
    </message>
    <message>
        <source>%1 lattice coordinates for %2 control points: give one [i, j] per control point</source>
        <translation>počet mřížových souřadnic (%1) neodpovídá počtu řídicích bodů (%2): zadejte jednu dvojici [i, j] pro každý řídicí bod</translation>
    </message>
    <message>
        <source>not the net of a %1 %2 patch: %3</source>
        <translation>není síť plátu %1 s rozložením %2: %3</translation>
    </message>
    <message>
        <source>map %1 does not exist: the %2 layout has maps 0 to %3</source>
        <translation>zobrazení %1 neexistuje: rozložení %2 má zobrazení 0 až %3</translation>
    </message>
    <message>
        <source>list each map once, in increasing order (0-based)</source>
        <translation>uveďte každé zobrazení jednou, ve vzestupném pořadí (číslováno od 0)</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceSchemeSpec</name>
    <message>
        <source>the %1 scheme has the layouts %2, not &apos;%3&apos;</source>
        <translation>schéma %1 má rozložení %2, ne „%3“</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceView</name>
    <message>
        <source>Drawing… (CPU renderer)</source>
        <translation>Kreslení… (vykreslování na CPU)</translation>
    </message>
    <message>
        <source>CPU renderer</source>
        <translation>Vykreslování na CPU</translation>
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
        <translation>hloubka %1 z %2 (rozpočet detailu: %3 tis. primitiv) · %4</translation>
    </message>
</context>
<context>
    <name>awb::UserGuideDialog</name>
    <message>
        <source>&lt;p&gt;The guide is missing.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Příručka chybí.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Home or F</source>
        <translation>Home nebo F</translation>
    </message>
    <message>
        <source>Fit the attractor view to its content</source>
        <translation>Přizpůsobit pohled atraktoru jeho obsahu</translation>
    </message>
    <message>
        <source>+ / −</source>
        <translation>+ / −</translation>
    </message>
    <message>
        <source>Zoom the attractor view in / out</source>
        <translation>Přiblížit / oddálit pohled atraktoru</translation>
    </message>
    <message>
        <source>Mouse wheel</source>
        <translation>Kolečko myši</translation>
    </message>
    <message>
        <source>Zoom at the cursor (view); scroll (panels)</source>
        <translation>Přiblížení v místě kurzoru (pohled); posouvání (panely)</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>Uživatelská příručka</translation>
    </message>
</context>
<context>
    <name>awb::ValenceChart</name>
    <message>
        <source>Valences: choose a mesh surface</source>
        <translation>Valence: vyberte plochu ze sítě</translation>
    </message>
    <message>
        <source>λ (subdominant)</source>
        <translation>λ (subdominantní)</translation>
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
        <translation>tato síť</translation>
    </message>
    <message>
        <source>λ, μ, λ² against n (%1)</source>
        <translation>λ, μ, λ² v závislosti na n (%1)</translation>
    </message>
    <message>
        <source>The subdominant eigenvalue λ, the next modulus μ and λ² of the local subdivision matrix at an interior vertex of valence n; the purple dots are this mesh&apos;s valences</source>
        <translation>Subdominantní vlastní číslo λ, následující modul μ a λ² lokální matice subdivize ve vnitřním vrcholu valence n; fialové body jsou valence této sítě</translation>
    </message>
    <message>
        <source>valence n</source>
        <translation>valence n</translation>
    </message>
    <message>
        <source>μ = λ² (bounded curvature)</source>
        <translation>μ = λ² (omezená křivost)</translation>
    </message>
    <message>
        <source>n = %1 … %2</source>
        <translation>n = %1 … %2</translation>
    </message>
    <message>
        <source>μ against λ²</source>
        <translation>μ v závislosti na λ²</translation>
    </message>
    <message>
        <source>Below the diagonal (μ &lt; λ²) the curvature at the vertex is zero, on it bounded, above it unbounded (for generic data)</source>
        <translation>Pod diagonálou (μ &lt; λ²) je křivost ve vrcholu nulová, na ní omezená, nad ní neomezená (pro generická data)</translation>
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
        <translation type="vanished">Nový graf vlastních čísel tohoto vrcholu</translation>
    </message>
    <message>
        <source>Adds an eigenvalue plot item whose source is this extraordinary vertex: its local subdivision matrix&apos;s eigenvalues, kept in the project and printed with it</source>
        <translation>Přidá položku grafu vlastních čísel, jejímž zdrojem je tento mimořádný vrchol: vlastní čísla jeho lokální matice subdivize, uložená v projektu a tištěná spolu s ním</translation>
    </message>
    <message>
        <source>Click an extraordinary vertex (a purple diamond labelled with its valence) in the 3D view of a mesh surface: its spectrum, Reif&apos;s verdict and its characteristic map appear here.</source>
        <translation>Klikněte na mimořádný vrchol (fialový kosočtverec označený jeho valencí) ve 3D pohledu plochy ze sítě: zde se zobrazí jeho spektrum, Reifův verdikt a charakteristické zobrazení.</translation>
    </message>
    <message>
        <source>valence %1, %2, %3</source>
        <translation type="vanished">valence %1, %2, %3</translation>
    </message>
    <message>
        <source>on the boundary</source>
        <translation>na hranici</translation>
    </message>
    <message>
        <source>interior</source>
        <translation>vnitřní</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the net of the vertex&apos;s piece).</source>
        <translation>Lokální matice subdivize S: %1 × %1 (síť části, k níž vrchol patří).</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the vertex and every point within two faces of it).</source>
        <translation>Lokální matice subdivize S: %1 × %1 (vrchol a všechny body vzdálené od něj nejvýše dvě stěny).</translation>
    </message>
    <message>
        <source>λ₁ = 1, λ = %1, μ = %2, λ² = %3</source>
        <translation>λ₁ = 1, λ = %1, μ = %2, λ² = %3</translation>
    </message>
    <message>
        <source> (λ in closed form: %1)</source>
        <translation type="vanished"> (λ v uzavřeném tvaru: %1)</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for interior vertices only: a boundary vertex follows the crease rules, whose analysis needs the boundary&apos;s own characteristic map.</source>
        <translation type="vanished">Reifovo kritérium se zde rozhoduje jen pro vnitřní vrcholy: hraniční vrchol se řídí pravidly pro ostré hrany, jejichž analýza vyžaduje vlastní charakteristické zobrazení hranice.</translation>
    </message>
    <message>
        <source>spectral condition 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ real</source>
        <translation>spektrální podmínka 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ reálné</translation>
    </message>
    <message>
        <source>characteristic map regular: the Jacobian keeps one sign on all %1 cells (signed areas %2 … %3)</source>
        <translation>charakteristické zobrazení je regulární: jakobián má na všech %1 buňkách stejné znaménko (orientované obsahy %2 … %3)</translation>
    </message>
    <message>
        <source>characteristic map not regular: signed areas from %1 to %2</source>
        <translation>charakteristické zobrazení není regulární: orientované obsahy od %1 do %2</translation>
    </message>
    <message>
        <source>characteristic map injective: its boundary winds %1 time(s) around the vertex</source>
        <translation>injektivita charakteristického zobrazení: jeho hranice oběhne vrchol %1krát</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): the limit surface is C¹ at the vertex (for generic data).</source>
        <translation>Verdikt (Reif 1995): limitní plocha je ve vrcholu C¹ (pro generická data).</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): C¹ is not established at the vertex.</source>
        <translation>Verdikt (Reif 1995): C¹ ve vrcholu není prokázáno.</translation>
    </message>
    <message>
        <source>μ &lt; λ²: the curvature is zero at the vertex (the surface is flat there to second order, for generic data: no convex or saddle shape can be modelled at it)</source>
        <translation>μ &lt; λ²: křivost ve vrcholu je nulová (pro generická data je tam plocha do druhého řádu rovinná: nelze v něm modelovat konvexní ani sedlový tvar)</translation>
    </message>
    <message>
        <source>μ = λ²: the curvature is bounded at the vertex</source>
        <translation>μ = λ²: křivost ve vrcholu je omezená</translation>
    </message>
    <message>
        <source>μ &gt; λ²: the curvature is unbounded at the vertex (for generic data)</source>
        <translation>μ &gt; λ²: křivost ve vrcholu je neomezená (pro generická data)</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3), normal (%4, %5, %6).</source>
        <translation>Limitní poloha (%1, %2, %3), normála (%4, %5, %6).</translation>
    </message>
    <message>
        <source>New Eigenvalue Plot</source>
        <translation>Nový graf vlastních čísel</translation>
    </message>
    <message>
        <source>; in closed form λ = %1 = %2</source>
        <translation>; v uzavřeném tvaru λ = %1 = %2</translation>
    </message>
    <message>
        <source>No spectrum: %1.</source>
        <translation>Bez spektra: %1.</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3).</source>
        <translation>Limitní poloha (%1, %2, %3).</translation>
    </message>
    <message>
        <source>a dart (one sharp edge ends here)</source>
        <translation>šipka (končí zde jedna ostrá hrana)</translation>
    </message>
    <message>
        <source>on a crease</source>
        <translation>na ostré hraně</translation>
    </message>
    <message>
        <source>a corner</source>
        <translation>roh</translation>
    </message>
    <message>
        <source>smooth</source>
        <translation>hladký</translation>
    </message>
    <message>
        <source>valence %1, %2, %3, %4</source>
        <translation>valence %1, %2, %3, %4</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for smooth interior vertices only: a boundary vertex or a sharp feature follows the crease rules, whose analysis needs the half-ring&apos;s own characteristic map.</source>
        <translation type="vanished">Reifovo kritérium se zde rozhoduje jen pro hladké vnitřní vrcholy: hraniční vrchol nebo ostrý prvek se řídí pravidly pro ostré hrany, jejichž analýza vyžaduje vlastní charakteristické zobrazení polovičního prstence.</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion sector by sector (Zorin 2000): each run of faces between sharp edges, with the eigenvalues whose eigenvectors do not vanish on it, on the canonical star of this neighbourhood:</source>
        <translation>Reifovo kritérium po sektorech (Zorin 2000): každý úsek stěn mezi ostrými hranami s vlastními čísly, jejichž vlastní vektory na něm nemizí, na kanonické hvězdě tohoto okolí:</translation>
    </message>
    <message>
        <source>face %1</source>
        <translation>stěna %1</translation>
    </message>
    <message>
        <source>faces %1–%2</source>
        <translation>stěny %1–%2</translation>
    </message>
    <message>
        <source>%1: λ₁ = %2, λ₂ = %3, μ = %4</source>
        <translation>%1: λ₁ = %2, λ₂ = %3, μ = %4</translation>
    </message>
    <message>
        <source>; C¹, curvature %1</source>
        <translation>; C¹, křivost %1</translation>
    </message>
    <message>
        <source>; not C¹: %1</source>
        <translation>; není C¹: %1</translation>
    </message>
    <message>
        <source>; %1</source>
        <translation>; %1</translation>
    </message>
    <message>
        <source>Verdict: the limit surface is C¹ on every sector up to the creases (for generic data).</source>
        <translation>Verdikt: limitní plocha je C¹ na každém sektoru až k ostrým hranám (pro generická data).</translation>
    </message>
    <message>
        <source>Verdict: C¹ is not established on every sector.</source>
        <translation>Verdikt: C¹ není na každém sektoru prokázáno.</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided for valences 3 to 64: this vertex is outside them.</source>
        <translation>Reifovo kritérium se rozhoduje pro valence 3 až 64: tento vrchol je mimo ně.</translation>
    </message>
    <message>
        <source>zero (μ &lt; λ₂²)</source>
        <translation>nulová (μ &lt; λ₂²)</translation>
    </message>
    <message>
        <source>bounded (μ = λ₂²)</source>
        <translation>omezená (μ = λ₂²)</translation>
    </message>
    <message>
        <source>unbounded (μ &gt; λ₂²)</source>
        <translation>neomezená (μ &gt; λ₂²)</translation>
    </message>
</context>
<context>
    <name>awb::analysis</name>
    <message>
        <source>cannot index an empty point set</source>
        <translation>prázdnou množinu bodů nelze indexovat</translation>
    </message>
    <message>
        <source>point sets must have 1 to 3 coordinates</source>
        <translation>množiny bodů musí mít 1 až 3 souřadnice</translation>
    </message>
    <message>
        <source>point set</source>
        <translation>množina bodů</translation>
    </message>
    <message>
        <source>point sets of different dimensions</source>
        <translation>množiny bodů různých dimenzí</translation>
    </message>
    <message>
        <source>too few points for box counting</source>
        <translation>příliš málo bodů pro počítání krabic</translation>
    </message>
    <message>
        <source>all points coincide</source>
        <translation>všechny body splývají</translation>
    </message>
    <message>
        <source>not enough points for three box sizes with at least %1 points per box</source>
        <translation>nedostatek bodů pro tři velikosti krabic s alespoň %1 body na krabici</translation>
    </message>
    <message>
        <source>the joint spectral radius needs at least one matrix</source>
        <translation>společný spektrální poloměr vyžaduje alespoň jednu matici</translation>
    </message>
    <message>
        <source>the joint spectral radius needs square matrices of one size; matrix %1 differs</source>
        <translation>společný spektrální poloměr vyžaduje čtvercové matice stejného rozměru; matice %1 se liší</translation>
    </message>
    <message>
        <source>matrix %1</source>
        <translation>matice %1</translation>
    </message>
    <message>
        <source>not convergent: the first difference scheme does not contract (JSR &gt;= 1)</source>
        <translation>nekonverguje: první diferenční schéma není kontraktivní (JSR &gt;= 1)</translation>
    </message>
    <message>
        <source>convergence not certified within the time budget</source>
        <translation>konvergenci se v rámci časového limitu nepodařilo ověřit</translation>
    </message>
    <message>
        <source>C^%1, Hölder regularity in [%2, %3]</source>
        <translation>C^%1, Hölderovská regularita v [%2, %3]</translation>
    </message>
    <message>
        <source>cancelled; the bounds are those reached. </source>
        <translation>zrušeno; uvedené meze jsou ty dosud dosažené. </translation>
    </message>
    <message>
        <source>time budget spent; the bounds are those reached. </source>
        <translation>časový limit vyčerpán; uvedené meze jsou ty dosud dosažené. </translation>
    </message>
    <message>
        <source>not convergent</source>
        <translation>nekonverguje</translation>
    </message>
    <message>
        <source>C^0 not certified</source>
        <translation>C^0 neověřeno</translation>
    </message>
    <message>
        <source>the arity of a scheme must be at least 2, got %1</source>
        <translation>arita schématu musí být alespoň 2, zadáno %1</translation>
    </message>
    <message>
        <source>the mask has a coefficient that is not a finite number</source>
        <translation>maska obsahuje koeficient, který není konečné číslo</translation>
    </message>
    <message>
        <source>no difference scheme: the mask is zero</source>
        <translation>diferenční schéma neexistuje: maska je nulová</translation>
    </message>
    <message>
        <source>no difference scheme: the symbol a(z) has no factor 1 + z%1 (the rules&apos; weights do not each sum to 1), so the scheme does not reproduce constants and is not convergent</source>
        <translation>diferenční schéma neexistuje: symbol a(z) nemá faktor 1 + z%1 (součet vah každého pravidla není 1), takže schéma nereprodukuje konstanty a nekonverguje</translation>
    </message>
    <message>
        <source>not convergent: the mask sums to %1, not the arity %2 (the scheme does not reproduce constants)</source>
        <translation>nekonverguje: součet masky je %1, nikoli arita %2 (schéma nereprodukuje konstanty)</translation>
    </message>
    <message>
        <source>the upper bound is the exact Hölder exponent only if the integer shifts of the basic limit function are stable (not checked for this mask). </source>
        <translation>horní mez je přesným Hölderovým exponentem jen tehdy, jsou-li celočíselné posuny základní limitní funkce stabilní (pro tuto masku neověřeno). </translation>
    </message>
    <message>
        <source>regularity needs at least two subdivision matrices</source>
        <translation>regularita vyžaduje alespoň dvě subdivizní matice</translation>
    </message>
    <message>
        <source>the subdivision matrices must all be square and of one size</source>
        <translation>subdivizní matice musí být všechny čtvercové a stejného rozměru</translation>
    </message>
    <message>
        <source>matrix S_%1</source>
        <translation>matice S_%1</translation>
    </message>
    <message>
        <source>no difference scheme: the rows of S_%1 do not all sum to 1</source>
        <translation>diferenční schéma neexistuje: součty řádků S_%1 nejsou všechny rovny 1</translation>
    </message>
    <message>
        <source>no regularity: S_1 or S_p has no simple eigenvalue 1, so the curve&apos;s end points are not defined</source>
        <translation>bez regularity: S_1 nebo S_p nemá jednoduché vlastní číslo 1, takže koncové body křivky nejsou definovány</translation>
    </message>
    <message>
        <source>no regularity: the pieces S_%1 and S_%2 do not join (the attractor is not a continuous curve in its %3-adic parameter)</source>
        <translation>bez regularity: části S_%1 a S_%2 na sebe nenavazují (atraktor není spojitá křivka ve svém %3-adickém parametru)</translation>
    </message>
    <message>
        <source>C^infinity: the curve is one polynomial piece of degree %1</source>
        <translation>C^infinity: křivka je jediný polynomiální úsek stupně %1</translation>
    </message>
    <message>
        <source>the matrices reproduce every polynomial of degree &lt; %1 in the %2-adic parameter and leave no complement</source>
        <translation>matice reprodukují každý polynom stupně &lt; %1 v %2-adickém parametru a nezbývá žádný doplněk</translation>
    </message>
    <message>
        <source>the upper bound assumes the curve&apos;s basis functions are stable. </source>
        <translation>horní mez předpokládá, že bázové funkce křivky jsou stabilní. </translation>
    </message>
    <message>
        <source>the pieces join only C^%1 (derivative %2 differs across a join). </source>
        <translation>části na sebe navazují jen se spojitostí C^%1 (derivace %2 se na spoji liší). </translation>
    </message>
    <message>
        <source>C^infinity: a Bézier curve is a polynomial of degree %1</source>
        <translation>C^infinity: Bézierova křivka je polynom stupně %1</translation>
    </message>
    <message>
        <source>de Casteljau subdivision reproduces the Bézier polynomial exactly</source>
        <translation>de Casteljauova subdivize reprodukuje Bézierův polynom přesně</translation>
    </message>
    <message>
        <source>eigenvalues need a square matrix</source>
        <translation>vlastní čísla vyžadují čtvercovou matici</translation>
    </message>
    <message>
        <source>matrix</source>
        <translation>matice</translation>
    </message>
    <message>
        <source>the eigenvalue computation did not converge</source>
        <translation>výpočet vlastních čísel nekonvergoval</translation>
    </message>
    <message>
        <source>no subdominant eigenvalue (the map is constant)</source>
        <translation>žádné subdominantní vlastní číslo (zobrazení je konstantní)</translation>
    </message>
    <message>
        <source>real positive: the curve has a half-tangent at the fixed point, along the eigenvector (G1 where the two sides&apos; eigenvectors align)</source>
        <translation>reálné kladné: křivka má v pevném bodě polotečnu ve směru vlastního vektoru (G1 tam, kde jsou vlastní vektory obou stran souhlasně rovnoběžné)</translation>
    </message>
    <message>
        <source>real positive but repeated: the tangent direction at the fixed point depends on the control points</source>
        <translation>reálné kladné, ale násobné: směr tečny v pevném bodě závisí na řídicích bodech</translation>
    </message>
    <message>
        <source>real negative: the curve oscillates at the fixed point and has no tangent there</source>
        <translation>reálné záporné: křivka v pevném bodě osciluje a nemá v něm tečnu</translation>
    </message>
    <message>
        <source>complex pair: the curve spirals around the fixed point (no tangent)</source>
        <translation>komplexně sdružená dvojice: křivka se kolem pevného bodu stáčí do spirály (bez tečny)</translation>
    </message>
    <message>
        <source>complex: near the fixed point the map acts as the spiral similarity z -&gt; lambda z, so the curve spirals around the fixed point (no tangent)</source>
        <translation>komplexní: v blízkosti pevného bodu působí zobrazení jako spirální podobnost z -&gt; lambda z, takže se křivka kolem pevného bodu stáčí do spirály (bez tečny)</translation>
    </message>
    <message>
        <source>several eigenvalues of the same modulus with different signs or phases: no single tangent behaviour</source>
        <translation>několik vlastních čísel se stejnou absolutní hodnotou a různými znaménky či fázemi: žádné jednotné chování tečny</translation>
    </message>
    <message>
        <source>not contractive: spectral radius %1 &gt;= 1</source>
        <translation>není kontraktivní: spektrální poloměr %1 &gt;= 1</translation>
    </message>
    <message>
        <source>contractive (factor ||A||_2 = %1)</source>
        <translation>kontraktivní (koeficient ||A||_2 = %1)</translation>
    </message>
    <message>
        <source>eventually contractive (spectral radius %1 &lt; 1; ||A^%2||_2 &lt; 1)</source>
        <translation>eventuálně kontraktivní (spektrální poloměr %1 &lt; 1; ||A^%2||_2 &lt; 1)</translation>
    </message>
    <message>
        <source>eventually contractive (spectral radius %1 &lt; 1)</source>
        <translation>eventuálně kontraktivní (spektrální poloměr %1 &lt; 1)</translation>
    </message>
    <message>
        <source>map %1 is not contractive: the spectral radius of its linear part is %2 &gt;= 1, so the IFS has no attractor (the iteration does not converge)</source>
        <translation>zobrazení %1 není kontraktivní: spektrální poloměr jeho lineární části je %2 &gt;= 1, takže IFS nemá atraktor (iterace nekonverguje)</translation>
    </message>
    <message>
        <source>too many points to index</source>
        <translation>příliš mnoho bodů k indexování</translation>
    </message>
    <message>
        <source>; but the IFS contracts on average (Lyapunov exponent %1 along the orbit): random iteration draws its attractor</source>
        <translation>; IFS se ale v průměru zkracuje (Ljapunovův exponent %1 podél orbity): náhodná iterace jeho atraktor vykreslí</translation>
    </message>
    <message>
        <source>a curve needs at least one piece</source>
        <translation>křivka potřebuje alespoň jeden úsek</translation>
    </message>
    <message>
        <source>a Bézier piece needs 2 to 31 plane control points</source>
        <translation>Bézierův úsek potřebuje 2 až 31 řídicích bodů v rovině</translation>
    </message>
    <message>
        <source>a Bézier piece</source>
        <translation>Bézierův úsek</translation>
    </message>
    <message>
        <source>a Takagi image needs 2 to 31 control points</source>
        <translation>Takagiho obraz potřebuje 2 až 31 řídicích bodů</translation>
    </message>
    <message>
        <source>the control points</source>
        <translation>řídicí body</translation>
    </message>
    <message>
        <source>a Takagi image needs a finite |y| &lt;= 1</source>
        <translation>Takagiho obraz potřebuje konečné |y| &lt;= 1</translation>
    </message>
    <message>
        <source>the Hausdorff bracket needs a nonempty set of plane points</source>
        <translation>interval (ohraničení) Hausdorffovy vzdálenosti potřebuje neprázdnou množinu bodů v rovině</translation>
    </message>
    <message>
        <source>the point set</source>
        <translation>množina bodů</translation>
    </message>
    <message>
        <source>the s.m.p. candidate&apos;s leading eigenvalue is complex (%1); the complex-polytope variant is not implemented</source>
        <translation>vedoucí vlastní číslo kandidáta na s.m.p. je komplexní (%1); varianta s komplexním polytopem není implementována</translation>
    </message>
    <message>
        <source>the s.m.p. candidate&apos;s leading eigenvalue is not simple in modulus (not a dominant product)</source>
        <translation>vedoucí vlastní číslo kandidáta na s.m.p. není jednoduché v absolutní hodnotě (nejde o dominantní součin)</translation>
    </message>
    <message>
        <source>no real leading eigenvector</source>
        <translation>žádný reálný vedoucí vlastní vektor</translation>
    </message>
    <message>
        <source>invariant polytope: cancelled</source>
        <translation>invariantní polytop: zrušeno</translation>
    </message>
    <message>
        <source>invariant polytope did not close in the budget (%1 vertices)</source>
        <translation>invariantní polytop se v rámci rozpočtu neuzavřel (vrcholů: %1)</translation>
    </message>
    <message>
        <source>invariant polytope did not close within %1 vertices</source>
        <translation>invariantní polytop se neuzavřel do %1 vrcholů</translation>
    </message>
    <message>
        <source>JSR = 0: the matrices are empty or zero</source>
        <translation>JSR = 0: matice jsou prázdné nebo nulové</translation>
    </message>
    <message>
        <source>every product up to length %1 has spectral radius 0: no s.m.p. candidate</source>
        <translation>každý součin do délky %1 má spektrální poloměr 0: žádný kandidát na s.m.p.</translation>
    </message>
    <message>
        <source>the family is numerically nilpotent (every product of length L vanishes to rounding): JSR = 0, no s.m.p. to certify</source>
        <translation>rodina je numericky nilpotentní (každý součin délky L je až na zaokrouhlení nulový): JSR = 0, žádný s.m.p. k certifikaci</translation>
    </message>
    <message>
        <source>the invariant polytope closed but its certificate failed the check: </source>
        <translation>invariantní polytop se uzavřel, ale jeho certifikát neprošel kontrolou: </translation>
    </message>
    <message>
        <source>invariant polytope closed: JSR = rho(A_w)^(1/%1) for the s.m.p. w = (%2), %3 vertices</source>
        <translation>invariantní polytop uzavřen: JSR = rho(A_w)^(1/%1) pro s.m.p. w = (%2), vrcholů: %3</translation>
    </message>
    <message>
        <source>the invariant polytope&apos;s bracket contradicts the bounds; ignored</source>
        <translation>interval (ohraničení) z invariantního polytopu odporuje mezím; ignorováno</translation>
    </message>
    <message>
        <source>the parameter range [%1, %2] must be finite with from &lt; to</source>
        <translation>rozsah parametru [%1, %2] musí být konečný, s počátkem menším než konec</translation>
    </message>
    <message>
        <source>the smoothness k must be between 0 and 30, got %1</source>
        <translation>hladkost k musí být mezi 0 a 30, zadáno %1</translation>
    </message>
    <message>
        <source>the grid must have 2 to 10000 values, got %1</source>
        <translation>mřížka musí mít 2 až 10000 hodnot, zadáno %1</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the mask is zero</source>
        <translation>žádný Sobolevův exponent: maska je nulová</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the symbol has no sum rule (the rules&apos; weights do not each sum to 1), so the scheme does not converge</source>
        <translation>žádný Sobolevův exponent: symbol nesplňuje žádné součtové pravidlo (váhy pravidel nemají každá součet 1), takže schéma nekonverguje</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the mask sums to %1, not the arity %2 (the refinement equation has no integrable solution with nonzero mean)</source>
        <translation>žádný Sobolevův exponent: součet masky je %1, nikoli arita %2 (zjemňovací rovnice nemá integrovatelné řešení s nenulovou střední hodnotou)</translation>
    </message>
    <message>
        <source>no positive Sobolev smoothness: rho = %1 &gt;= 1 (to rounding), so s_2 = %2 &lt;= 0: with stable shifts the basic limit function is in no H^s with s &gt; 0, if it is a function at all</source>
        <translation>žádná kladná Sobolevova hladkost: rho = %1 &gt;= 1 (až na zaokrouhlení), takže s_2 = %2 &lt;= 0: při stabilních posunutích neleží základní limitní funkce v žádném H^s s s &gt; 0, pokud je vůbec funkcí</translation>
    </message>
    <message>
        <source>Sobolev exponent s_2 = %1: in H^s for every s &lt; %1</source>
        <translation>Sobolevův exponent s_2 = %1: v H^s pro každé s &lt; %1</translation>
    </message>
    <message>
        <source> (capped at the %1 sum rules; -log_N(rho) / 2 = %2)</source>
        <translation> (shora omezeno počtem součtových pravidel, %1; -log_N(rho) / 2 = %2)</translation>
    </message>
    <message>
        <source>not analysed: the mask has %1 coefficients, the regularity analysis takes at most %2 for arity %3 (transition matrices up to 48 x 48)</source>
        <translation>neanalyzováno: maska má %1 koeficientů, analýza regularity přijme pro aritu %3 nejvýše %2 (přechodové matice do 48 x 48)</translation>
    </message>
    <message>
        <source>; exact by the invariant polytope algorithm (Guglielmi &amp; Protasov 2013): s.m.p. (%1), %2 vertices</source>
        <translation>; přesně algoritmem invariantního polytopu (Guglielmi &amp; Protasov 2013): s.m.p. (%1), vrcholů: %2</translation>
    </message>
    <message>
        <source>JSR of %1 matrices %2 x %2</source>
        <translation>JSR %1 matic %2 x %2</translation>
    </message>
    <message>
        <source>: lower bound max rho(product)^(1/k) over all products up to length %1</source>
        <translation>: dolní mez max rho(product)^(1/k) přes všechny součiny do délky %1</translation>
    </message>
    <message>
        <source> and the branch&apos;s products up to length %1</source>
        <translation> a součiny větvení do délky %1</translation>
    </message>
    <message>
        <source>, upper bound by Gripenberg&apos;s branch and bound (1996) in the %1</source>
        <translation>, horní mez Gripenbergovou metodou větví a mezí (1996) v %1</translation>
    </message>
    <message>
        <source>, upper bound in the %1</source>
        <translation>, horní mez v %1</translation>
    </message>
    <message>
        <source> (equal to the lower bound)</source>
        <translation> (rovná se dolní mezi)</translation>
    </message>
    <message>
        <source>, %1 products</source>
        <translation>, součinů: %1</translation>
    </message>
    <message>
        <source>r = n - log_%1 rho_n with n = %2 (a(z) has the factor (%3)^%2), rho_n the joint spectral radius of the transition matrices of the divided-difference mask of order %2 (Daubechies &amp; Lagarias 1992, Rioul 1992); %4%5</source>
        <translation>r = n - log_%1 rho_n, kde n = %2 (a(z) má faktor (%3)^%2) a rho_n je společný spektrální poloměr přechodových matic masky poměrných diferencí řádu %2 (Daubechies &amp; Lagarias 1992, Rioul 1992); %4%5</translation>
    </message>
    <message>
        <source>r = -log_%1 rho with rho the joint spectral radius of S_1..S_%1 on the quotient by the control vectors of the polynomials of degree &lt; %2 that they generate (Micchelli &amp; Prautzsch 1989); %3%4</source>
        <translation>r = -log_%1 rho, kde rho je společný spektrální poloměr S_1..S_%1 na faktorprostoru podle řídicích vektorů, které generují polynomy stupně &lt; %2 (Micchelli &amp; Prautzsch 1989); %3%4</translation>
    </message>
    <message>
        <source>s_2 = -log_%1(rho) / 2 with rho the spectral radius of the transition operator (T v)_i = sum_j b_{%1i - j} v_j of the autocorrelation b_k = (1/%1) sum_j a_j a_{j+k} on [-%2, %2], restricted to the %3-dimensional invariant subspace orthogonal to the polynomials of degree &lt; %4 (Eirola 1992, Villemoes 1994, Jia 1999); exact for stable integer shifts, a lower bound otherwise (Ron &amp; Shen 2000); rounding margin %5</source>
        <translation>s_2 = -log_%1(rho) / 2, kde rho je spektrální poloměr přechodového operátoru (T v)_i = sum_j b_{%1i - j} v_j autokorelace b_k = (1/%1) sum_j a_j a_{j+k} na [-%2, %2], zúženého na invariantní podprostor dimenze %3 ortogonální k polynomům stupně &lt; %4 (Eirola 1992, Villemoes 1994, Jia 1999); přesná hodnota při stabilních celočíselných posunech, jinak dolní mez (Ron &amp; Shen 2000); rezerva na zaokrouhlení %5</translation>
    </message>
    <message>
        <source>work budget spent; the bounds are those reached. </source>
        <translation>rozpočet práce vyčerpán; meze jsou ty dosažené. </translation>
    </message>
    <message>
        <source>an atlas has one or two parameters, got %1</source>
        <translation>atlas má jeden nebo dva parametry, zadáno: %1</translation>
    </message>
    <message>
        <source>a parameter of the atlas has no name</source>
        <translation>parametr atlasu nemá název</translation>
    </message>
    <message>
        <source>the range of %1, [%2, %3], must be finite with from &lt; to</source>
        <translation>rozsah %1, [%2, %3], musí být konečný a „od“ &lt; „do“</translation>
    </message>
    <message>
        <source>the grid of %1 must have 2 to %2 values, got %3</source>
        <translation>mřížka %1 musí mít 2 až %2 hodnot, zadáno: %3</translation>
    </message>
    <message>
        <source>the two parameters of the atlas have the same name %1</source>
        <translation>oba parametry atlasu mají stejný název %1</translation>
    </message>
    <message>
        <source>the tolerance must be a positive number</source>
        <translation>tolerance musí být kladné číslo</translation>
    </message>
    <message>
        <source>the sections per round must be 1 to 64</source>
        <translation>počet úseků na kolo musí být 1 až 64</translation>
    </message>
    <message>
        <source>the rounds must be 0 to 64</source>
        <translation>počet kol musí být 0 až 64</translation>
    </message>
    <message>
        <source>the refinement levels must be 0 to 10, got %1</source>
        <translation>počet úrovní zjemnění musí být 0 až 10, zadáno: %1</translation>
    </message>
    <message>
        <source>the work per point must be 1000 to 1e11 products</source>
        <translation>práce na bod musí být 1000 až 1e11 součinů</translation>
    </message>
    <message>
        <source>the polytope vertices must be 0 to 100000</source>
        <translation>počet vrcholů polytopu musí být 0 až 100000</translation>
    </message>
    <message>
        <source>the safety time must be 0 to 86400 s</source>
        <translation>bezpečnostní čas musí být 0 až 86400 s</translation>
    </message>
    <message>
        <source>a grid of %1 x %2 points is more than the atlas&apos;s 1e6</source>
        <translation>mřížka %1 x %2 bodů překračuje limit atlasu 1e6</translation>
    </message>
    <message>
        <source>the atlas&apos;s previous batch has no rows yet</source>
        <translation>předchozí dávka atlasu zatím nemá žádné řádky</translation>
    </message>
    <message>
        <source>the atlas expected %1 rows, got %2</source>
        <translation>očekávaný počet řádků atlasu: %1, přijato: %2</translation>
    </message>
    <message>
        <source>a row of the atlas does not belong to its batch</source>
        <translation>řádek atlasu nepatří do své dávky</translation>
    </message>
    <message>
        <source>map %1 is not contractive: its map of the plane has spectral radius %2 &gt;= 1 (%3 in the lifted space of its control points), so the IFS has no attractor (the iteration does not converge)</source>
        <translation>zobrazení %1 není kontraktivní: jeho zobrazení roviny má spektrální poloměr %2 &gt;= 1 (%3 ve zvednutém prostoru jeho řídicích bodů), takže IFS nemá atraktor (iterace nekonverguje)</translation>
    </message>
    <message>
        <source>map %1 is not contractive in the lifted space of its control points (spectral radius %3 &gt;= 1), although its map of the plane contracts (spectral radius %2): the lifted iteration does not converge</source>
        <translation>zobrazení %1 není kontraktivní ve zvednutém prostoru svých řídicích bodů (spektrální poloměr %3 &gt;= 1), ačkoli jeho zobrazení roviny je kontraktivní (spektrální poloměr %2): zvednutá iterace nekonverguje</translation>
    </message>
</context>
<context>
    <name>awb::cli</name>
    <message>
        <source>Render the bundled paper figures to PNG files (one row of panels per figure: the start set, a few iterates of the Hutchinson operator, and the attractor, over the control polygon).</source>
        <translation>Vykreslí přiložené obrázky z článků do souborů PNG (na každý obrázek jeden řádek panelů: počáteční množina, několik iterací Hutchinsonova operátoru a atraktor, vše nad řídicím polygonem).</translation>
    </message>
    <message>
        <source>Directory for the PNG files (created if missing).</source>
        <translation>Složka pro soubory PNG (vytvoří se, pokud neexistuje).</translation>
    </message>
    <message>
        <source>List the examples and exit.</source>
        <translation>Vypíše seznam příkladů a skončí.</translation>
    </message>
    <message>
        <source>attractor-cli: cannot create directory %1</source>
        <translation>attractor-cli: nelze vytvořit složku %1</translation>
    </message>
    <message>
        <source>attractor-cli: unknown command &apos;%1&apos;</source>
        <translation>attractor-cli: neznámý příkaz „%1“</translation>
    </message>
    <message>
        <source>expected %1 project file, got %2 arguments (see --help)</source>
        <translation>očekávaný počet projektových souborů: %1, zadáno argumentů: %2 (viz --help)</translation>
    </message>
    <message>
        <source>no item named &apos;%1&apos; in %2</source>
        <translation>v %2 není žádná položka s názvem „%1“</translation>
    </message>
    <message>
        <source>the figure&apos;s project</source>
        <translation>projektu obrázku</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no attractor</source>
        <translation>položka „%1“ (%2) nemá atraktor</translation>
    </message>
    <message>
        <source>%1 has no item with an attractor</source>
        <translation>%1 neobsahuje žádnou položku s atraktorem</translation>
    </message>
    <message>
        <source>item &apos;%1&apos;: %2</source>
        <translation>položka „%1“: %2</translation>
    </message>
    <message>
        <source>--%1 must be a whole number from %2 to %3, got &apos;%4&apos;</source>
        <translation>--%1 musí být celé číslo od %2 do %3, zadáno „%4“</translation>
    </message>
    <message>
        <source>--%1 must be a number from %2 to %3, got &apos;%4&apos;</source>
        <translation>--%1 musí být číslo od %2 do %3, zadáno „%4“</translation>
    </message>
    <message>
        <source>--start: &apos;%1&apos; is not a finite number</source>
        <translation type="vanished">--start: „%1“ není konečné číslo</translation>
    </message>
    <message>
        <source>--start must be point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;..., got &apos;%1&apos;</source>
        <translation type="vanished">--start musí mít tvar point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;..., zadáno „%1“</translation>
    </message>
    <message>
        <source>--start %1 needs %2 coordinates (%3 per point), got %4</source>
        <translation type="vanished">--start %1: počet souřadnic musí být %2 (%3 na bod), zadáno %4</translation>
    </message>
    <message>
        <source>a multiple of %1</source>
        <translation type="vanished">násobek %1</translation>
    </message>
    <message>
        <source>depth %1 gives %2 points, more than --max-points %3</source>
        <translation>hloubka %1 dává %2 bodů, více než --max-points %3</translation>
    </message>
    <message>
        <source>Image size in pixels (default 900x700).</source>
        <translation>Velikost obrázku v pixelech (výchozí 900x700).</translation>
    </message>
    <message>
        <source>Deterministic iteration depth (default: the item&apos;s).</source>
        <translation>Deterministická hloubka iterace (výchozí: podle položky).</translation>
    </message>
    <message>
        <source>Random iteration with this many points (up to 1e12; memory stays that of the raster).</source>
        <translation>Náhodná iterace s tímto počtem bodů (až 1e12; paměťová náročnost zůstává na úrovni rastru).</translation>
    </message>
    <message>
        <source>Raster tone: &apos;hits&apos; (every lit pixel opaque, the papers&apos; look) or &apos;density&apos; (log density of the invariant measure, gamma and vibrancy as flame renderers). Default: the item&apos;s style (auto: hits for deterministic, density for random iteration).</source>
        <translation>Tón rastru: &apos;hits&apos; (každý zasažený pixel je neprůhledný, vzhled jako v článcích) nebo &apos;density&apos; (logaritmická hustota invariantní míry, gama a sytost jako ve flame rendererech). Výchozí: styl položky (auto: hits pro deterministickou, density pro náhodnou iteraci).</translation>
    </message>
    <message>
        <source>Density tone: display gamma (default: the item&apos;s, 2.2).</source>
        <translation>Tón density: gama zobrazení (výchozí: podle položky, 2.2).</translation>
    </message>
    <message>
        <source>Density tone: 1 saturated colours, 0 per-channel gamma (default 1).</source>
        <translation>Tón density: 1 syté barvy, 0 gama po jednotlivých kanálech (výchozí 1).</translation>
    </message>
    <message>
        <source>Histogram cells per pixel side, 1..4 (default 1; 2 or 3 anti-alias edges).</source>
        <translation>Počet buněk histogramu na stranu pixelu, 1..4 (výchozí 1; 2 nebo 3 vyhlazují hrany).</translation>
    </message>
    <message>
        <source>Threads of the raster engine (default: all cores).</source>
        <translation>Počet vláken rastrovacího modulu (výchozí: všechna jádra).</translation>
    </message>
    <message>
        <source>Surfaces: the camera&apos;s azimuth and elevation in degrees (orthographic; default: the item&apos;s camera).</source>
        <translation>Plochy: azimut a elevace kamery ve stupních (ortografická projekce; výchozí: kamera položky).</translation>
    </message>
    <message>
        <source>Plane figures: the world rectangle to frame (padded by 6%), e.g. to compare figures at one scale (default: fit the content).</source>
        <translation>Rovinné obrázky: obdélník ve světových souřadnicích, který se má zobrazit (s okrajem 6 %), např. pro porovnání obrázků ve stejném měřítku (výchozí: přizpůsobit obsahu).</translation>
    </message>
    <message>
        <source>The output&apos;s format when its name has no suffix (e.g. /dev/stdout): png, svg or pdf (default: the suffix).</source>
        <translation type="vanished">Formát výstupu, pokud jeho název nemá příponu (např. /dev/stdout): png, svg nebo pdf (výchozí: podle přípony).</translation>
    </message>
    <message>
        <source>--depth and --samples exclude each other</source>
        <translation>--depth a --samples se navzájem vylučují</translation>
    </message>
    <message>
        <source>--size must be WxH with 64..16384 pixels each, got &apos;%1&apos;</source>
        <translation>--size musí mít tvar ŠxV s 64..16384 pixely v každém rozměru, zadáno „%1“</translation>
    </message>
    <message>
        <source>--tone must be &apos;hits&apos; or &apos;density&apos;, got &apos;%1&apos;</source>
        <translation>--tone musí být &apos;hits&apos; nebo &apos;density&apos;, zadáno „%1“</translation>
    </message>
    <message>
        <source>--bounds must be x0,y0,x1,y1 with x0 &lt; x1 and y0 &lt; y1, got &apos;%1&apos;</source>
        <translation>--bounds musí mít tvar x0,y0,x1,y1 s x0 &lt; x1 a y0 &lt; y1, zadáno „%1“</translation>
    </message>
    <message>
        <source>--format must be png, svg or pdf, got &apos;%1&apos;</source>
        <translation type="vanished">--format musí být png, svg nebo pdf, zadáno „%1“</translation>
    </message>
    <message>
        <source>depth %1 makes %2 images; at most 4e9 are rendered</source>
        <translation type="vanished">hloubka %1 dává %2 obrazů; vykresluje se nejvýše 4e9</translation>
    </message>
    <message>
        <source>--view must be AZ,EL in degrees with |EL| &lt;= 90, got &apos;%1&apos;</source>
        <translation>--view musí mít tvar AZ,EL ve stupních s |EL| &lt;= 90, zadáno „%1“</translation>
    </message>
    <message>
        <source>%1 random points</source>
        <translation type="vanished">%1 náhodných bodů</translation>
    </message>
    <message>
        <source>F^%1(X0)</source>
        <translation type="vanished">F^%1(X0)</translation>
    </message>
    <message>
        <source>, maps %1 of %2</source>
        <translation type="vanished">, zobrazení %1 z %2</translation>
    </message>
    <message>
        <source>%1: %2%3 — orthographic view from azimuth %4°, elevation %5°</source>
        <translation type="vanished">%1: %2%3 — ortografický pohled z azimutu %4°, elevace %5°</translation>
    </message>
    <message>
        <source>%1: %2 random points</source>
        <translation type="vanished">%1: %2 náhodných bodů</translation>
    </message>
    <message>
        <source>%1: F^%2(X0)</source>
        <translation type="vanished">%1: F^%2(X0)</translation>
    </message>
    <message>
        <source>%1: polygon after %2 steps</source>
        <translation type="vanished">%1: polygon po kroku %2</translation>
    </message>
    <message>
        <source>Render an item&apos;s attractor (with its control polygons) to PNG, SVG or PDF.</source>
        <translation type="vanished">Vykreslí atraktor položky (s jejími řídicími polygony) do PNG, SVG nebo PDF.</translation>
    </message>
    <message>
        <source>The .awb project file.</source>
        <translation>Projektový soubor .awb.</translation>
    </message>
    <message>
        <source>The item to render (default: the first with an attractor).</source>
        <translation>Položka, která se má vykreslit (výchozí: první položka s atraktorem).</translation>
    </message>
    <message>
        <source>Output file: .png, .svg or .pdf.</source>
        <translation type="vanished">Výstupní soubor: .png, .svg nebo .pdf.</translation>
    </message>
    <message>
        <source>--out FILE is required</source>
        <translation>--out FILE je povinné</translation>
    </message>
    <message>
        <source>Render the frames of an item&apos;s animation (its keyframed parameters): numbered PNG files in a folder, or an MP4 or GIF movie through ffmpeg. Frame k is the item with its parameters at time k / fps, drawn exactly as `render` draws it.</source>
        <translation>Vykreslí snímky animace položky (jejích parametrů s klíčovými snímky): číslované soubory PNG ve složce, nebo film MP4 či GIF pomocí ffmpeg. Snímek k je položka s parametry v čase k / fps, vykreslená přesně tak, jak ji vykresluje `render`.</translation>
    </message>
    <message>
        <source>The animated item (default: the first item with an animation).</source>
        <translation>Animovaná položka (výchozí: první položka s animací).</translation>
    </message>
    <message>
        <source>A folder for frame-0000.png, frame-0001.png, ... (made if missing), a movie .mp4 or .gif (made by ffmpeg), or with --frame one .png/.svg/.pdf.</source>
        <translation>Složka pro frame-0000.png, frame-0001.png, ... (vytvoří se, pokud neexistuje), film .mp4 nebo .gif (vytvoří ho ffmpeg), nebo s --frame jeden soubor .png/.svg/.pdf.</translation>
    </message>
    <message>
        <source>Frames per second (default: the animation&apos;s).</source>
        <translation>Počet snímků za sekundu (výchozí: podle animace).</translation>
    </message>
    <message>
        <source>Render only frame K (0 = the start) to the file --out.</source>
        <translation>Vykreslí jen snímek K (0 = začátek) do souboru --out.</translation>
    </message>
    <message>
        <source>Captions without the frame&apos;s time and values.</source>
        <translation>Popisky bez času a hodnot snímku.</translation>
    </message>
    <message>
        <source>--out DIR|FILE is required</source>
        <translation>--out DIR|FILE je povinné</translation>
    </message>
    <message>
        <source>%1 has no animated item</source>
        <translation>%1 neobsahuje žádnou animovanou položku</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; has no animation: key its parameters in the Animation dock, or give it an &quot;animation&quot; field (docs/file-format.md)</source>
        <translation>položka „%1“ nemá animaci: nastavte klíče jejích parametrů v panelu Animace, nebo jí přidejte pole &quot;animation&quot; (docs/file-format.md)</translation>
    </message>
    <message>
        <source>attractor-cli: note: the track of %1 is skipped: item &apos;%2&apos; has no such input now</source>
        <translation>attractor-cli: poznámka: stopa %1 se přeskakuje: položka „%2“ nyní takový vstup nemá</translation>
    </message>
    <message>
        <source>%1,%2,%3,%4</source>
        <translation>%1,%2,%3,%4</translation>
    </message>
    <message>
        <source>fitted per frame</source>
        <translation>přizpůsobeno každému snímku</translation>
    </message>
    <message>
        <source>frame %1 (t = %2 s): %3</source>
        <translation>snímek %1 (t = %2 s): %3</translation>
    </message>
    <message>
        <source>writing %1 needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg); give --out a folder to get the frames as PNG files</source>
        <translation>zápis %1 vyžaduje ffmpeg, který není nainstalován (Debian: apt-get install ffmpeg); chcete-li snímky jako soubory PNG, zadejte v --out složku</translation>
    </message>
    <message>
        <source>cannot make a temporary folder for the frames: %1</source>
        <translation>nelze vytvořit dočasnou složku pro snímky: %1</translation>
    </message>
    <message>
        <source>%1 is a file, not a folder (a movie needs .mp4 or .gif)</source>
        <translation>%1 je soubor, ne složka (film vyžaduje .mp4 nebo .gif)</translation>
    </message>
    <message>
        <source>cannot make the folder %1</source>
        <translation>nelze vytvořit složku %1</translation>
    </message>
    <message>
        <source>frame-%1.png</source>
        <translation>frame-%1.png</translation>
    </message>
    <message>
        <source>ffmpeg could not write %1: %2</source>
        <translation>ffmpeg nemohl zapsat %1: %2</translation>
    </message>
    <message>
        <source>%1: %2 frames of %3x%4 at %5 frames/s (%6 s); rendered in %7 s, %8 frames/s
bounds: %9
</source>
        <translation>%1: snímků: %2, %3x%4 při %5 snímcích/s (%6 s); vykresleno za %7 s, %8 snímků/s
meze: %9
</translation>
    </message>
    <message>
        <source>Analyse the items of a project: per map S_i (exact fractions), M_i = P^-1 S_i P with its blocks A_i, b_i, the eigenvalues of S_i and A_i, spectral radius, contractivity and fixed point; per item the subdominant eigenvalues, the Hausdorff distance to the exact curve and the box-counting dimension; per subdivision curve the certified Hölder regularity of its scheme.</source>
        <translation>Analyzuje položky projektu: pro každé zobrazení S_i (přesné zlomky), M_i = P^-1 S_i P s bloky A_i, b_i, vlastní čísla S_i a A_i, spektrální poloměr, kontraktivitu a pevný bod; pro každou položku subdominantní vlastní čísla, Hausdorffovu vzdálenost od přesné křivky a dimenzi určenou počítáním krabic; pro každou subdivizní křivku ověřenou Hölderovskou regularitu jejího schématu.</translation>
    </message>
    <message>
        <source>Only this item.</source>
        <translation>Jen tato položka.</translation>
    </message>
    <message>
        <source>Print JSON (the only format so far).</source>
        <translation>Vypsat JSON (zatím jediný formát).</translation>
    </message>
    <message>
        <source>--json is required (the only output format)</source>
        <translation>--json je povinné (jediný výstupní formát)</translation>
    </message>
    <message>
        <source>Print the points of F^k(X0) as CSV: x, y (and z for a surface), the map applied last (1-based), and the view. --address w limits them to the sub-copy f_w(A): the points f_w(F^k(X0)).</source>
        <translation>Vypíše body F^k(X0) jako CSV: x, y (u plochy i z), naposledy použité zobrazení (číslováno od 1) a pohled. --address w je omezí na dílčí kopii f_w(A): body f_w(F^k(X0)).</translation>
    </message>
    <message>
        <source>The item.</source>
        <translation type="vanished">Položka.</translation>
    </message>
    <message>
        <source>Iteration depth (default: the item&apos;s).</source>
        <translation>Hloubka iterace (výchozí: podle položky).</translation>
    </message>
    <message>
        <source>Print CSV (the only format so far).</source>
        <translation>Vypsat CSV (zatím jediný formát).</translation>
    </message>
    <message>
        <source>Only the sub-copy f_w(A) of this address: 0-based map numbers, w_1 (the outermost map) first, e.g. 0,1,1.</source>
        <translation>Jen dílčí kopie f_w(A) této adresy: čísla zobrazení od 0, jako první w_1 (vnější zobrazení), např. 0,1,1.</translation>
    </message>
    <message>
        <source>Refuse to print more (default 10000000).</source>
        <translation>Nevypisovat více bodů než tento počet (výchozí 10000000).</translation>
    </message>
    <message>
        <source>--item NAME is required</source>
        <translation type="vanished">--item NAME je povinné</translation>
    </message>
    <message>
        <source>--csv is required (the only output format)</source>
        <translation>--csv je povinné (jediný výstupní formát)</translation>
    </message>
    <message>
        <source>--address %1: %2</source>
        <translation>--address %1: %2</translation>
    </message>
    <message>
        <source>--start lifted: needs at least one point</source>
        <translation type="vanished">--start lifted: vyžaduje alespoň jeden bod</translation>
    </message>
    <message>
        <source>cannot write to the standard output</source>
        <translation>nelze zapisovat na standardní výstup</translation>
    </message>
    <message>
        <source>Validate a project file: it must load, and every item&apos;s IFS must be computable (exit 1: the file is refused; exit 3: it loads but items cannot be computed).</source>
        <translation>Ověří projektový soubor: musí se načíst a IFS každé položky musí být vypočitatelný (návratový kód 1: soubor je odmítnut; návratový kód 3: načte se, ale položky nelze vypočítat).</translation>
    </message>
    <message>
        <source>%1: %2: note: %3</source>
        <translation>%1: %2: poznámka: %3</translation>
    </message>
    <message>
        <source>Load a project and save it again in the canonical form of this version (sorted keys, every field written): to upgrade or normalise a hand-written file.</source>
        <translation>Načte projekt a znovu ho uloží v kanonickém tvaru této verze (seřazené klíče, zapsána všechna pole): slouží k aktualizaci nebo normalizaci ručně psaného souboru.</translation>
    </message>
    <message>
        <source>Write here instead of over the input.</source>
        <translation>Zapsat sem místo přepsání vstupu.</translation>
    </message>
    <message>
        <source>v %1 %2 %3
</source>
        <translation>v %1 %2 %3
</translation>
    </message>
    <message>
        <source>ply (attractor points) or obj (subdivided mesh).</source>
        <translation type="vanished">ply (body atraktoru) nebo obj (zjemněná síť).</translation>
    </message>
    <message>
        <source>Output file.</source>
        <translation>Výstupní soubor.</translation>
    </message>
    <message>
        <source>PLY: iteration depth (default: the item&apos;s).</source>
        <translation>PLY: hloubka iterace (výchozí: podle položky).</translation>
    </message>
    <message>
        <source>PLY: refuse to write more (default 50000000).</source>
        <translation>PLY: nezapisovat více bodů než tento počet (výchozí 50000000).</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj and --out FILE are required</source>
        <translation type="vanished">--item NAME, --format ply|obj a --out FILE jsou povinné</translation>
    </message>
    <message>
        <source>--format must be ply or obj, got &apos;%1&apos;</source>
        <translation type="vanished">--format musí být ply nebo obj, zadáno „%1“</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 nelze zapsat: %2</translation>
    </message>
    <message>
        <source>OBJ export writes the subdivided net of a surface item; &apos;%1&apos; is a %2</source>
        <translation>export do OBJ zapisuje zjemněnou síť plošné položky; „%1“ je typu %2</translation>
    </message>
    <message>
        <source>Print the control polygon after K subdivision steps as JSON {&quot;closed&quot;, &quot;points&quot;}: the figures of 001 for a normal-vector item (eq. (1) applied K times), classic subdivision S_w P for a subdivision curve.</source>
        <translation>Vypíše řídicí polygon po K krocích subdivize jako JSON {&quot;closed&quot;, &quot;points&quot;}: obrázky z 001 pro položku s normálovými vektory (eq. (1) použitá K-krát), klasickou subdivizi S_w P pro subdivizní křivku.</translation>
    </message>
    <message>
        <source>Subdivision steps K (0: the control polygon).</source>
        <translation>Počet kroků subdivize K (0: řídicí polygon).</translation>
    </message>
    <message>
        <source>Print JSON (the only format).</source>
        <translation>Vypsat JSON (jediný formát).</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; has a complex split parameter: its control polygon has complex points</source>
        <translation>položka „%1“ má komplexní parametr dělení: její řídicí polygon má komplexní body</translation>
    </message>
    <message>
        <source>level %1 gives more than 5e7 points</source>
        <translation>úroveň %1 dává více než 5e7 bodů</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) is not polygon-based: the polygon command takes normal-vector items and subdivision curves</source>
        <translation>položka „%1“ (%2) není založena na polygonu: příkaz polygon přijímá položky s normálovými vektory a subdivizní křivky</translation>
    </message>
    <message>
        <source>nothing to draw</source>
        <translation>není co kreslit</translation>
    </message>
    <message>
        <source>Make a project of a mesh file (OBJ, OFF, PLY ASCII or binary): one subdivision-mesh item with the file&apos;s vertices, in its numbering, and its polygons.</source>
        <translation type="vanished">Vytvoří projekt ze souboru sítě (OBJ, OFF, PLY ASCII nebo binární): jednu položku subdivision-mesh s vrcholy souboru v jeho číslování a s jeho polygony.</translation>
    </message>
    <message>
        <source>The mesh file.</source>
        <translation>Soubor sítě.</translation>
    </message>
    <message>
        <source>catmull-clark (any polygons, the default) or loop (triangles).</source>
        <translation>catmull-clark (libovolné polygony, výchozí) nebo loop (trojúhelníky).</translation>
    </message>
    <message>
        <source>The project file to write (.awb).</source>
        <translation>Projektový soubor, který se má zapsat (.awb).</translation>
    </message>
    <message>
        <source>The item&apos;s name (default: the file&apos;s base name).</source>
        <translation>Název položky (výchozí: název souboru bez přípony).</translation>
    </message>
    <message>
        <source>--scheme must be catmull-clark or loop, got &apos;%1&apos;</source>
        <translation>--scheme musí být catmull-clark nebo loop, zadáno „%1“</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be an item&apos;s name</source>
        <translation>„%1“ nemůže být názvem položky</translation>
    </message>
    <message>
        <source>%1: item &apos;%2&apos;, %3 vertices, %4 faces, %5 extraordinary vertices (%6)
</source>
        <translation>%1: položka „%2“, %3 vrcholů, %4 stěn, %5 mimořádných vrcholů (%6)
</translation>
    </message>
    <message>
        <source>attractor-cli: note: %1</source>
        <translation type="vanished">attractor-cli: poznámka: %1</translation>
    </message>
    <message>
        <source>Start set: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (plane coordinates; x,y,z for a surface) | lifted:x,y,c1,...;x,y,c1,... (points of the lifted space of 000 §2) | vertex-limits (a mesh item: the limit positions of the vertices of the mesh refined k times; default: the item&apos;s).</source>
        <translation type="vanished">Počáteční množina: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (rovinné souřadnice; u plochy x,y,z) | lifted:x,y,c1,...;x,y,c1,... (body zdviženého prostoru z 000 §2) | vertex-limits (položka se sítí: limitní polohy vrcholů sítě zjemněné k-krát; výchozí: podle položky).</translation>
    </message>
    <message>
        <source>--start vertex-limits needs a mesh item; &apos;%1&apos; is a %2</source>
        <translation type="vanished">--start vertex-limits vyžaduje položku se sítí; „%1“ je typu %2</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ).</source>
        <translation type="vanished">Exportuje geometrii položky: atraktor F^k(X0) jako mračno bodů PLY (u každého bodu s naposledy použitým zobrazením), síť plošné položky po k kolech klasické subdivize jako polygonovou síť OBJ, nebo položku se sítí po k krocích s každým vrcholem v jeho limitní poloze (OBJ).</translation>
    </message>
    <message>
        <source>OBJ: rounds of subdivision (default: the item&apos;s; a mesh item: its depth, at most 6).</source>
        <translation>OBJ: počet kol subdivize (výchozí: podle položky; u položky se sítí její hloubka, nejvýše 6).</translation>
    </message>
    <message>
        <source>%1 steps give %2 vertices: too many</source>
        <translation type="vanished">%1 kroků dává %2 vrcholů: příliš mnoho</translation>
    </message>
    <message>
        <source>Attractor Workbench: item %1, %2 after %3 steps, every vertex at its limit position</source>
        <translation type="vanished">Attractor Workbench: položka %1, %2 po %3 krocích, každý vrchol v limitní poloze</translation>
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
        <translation type="vanished">Použití: attractor-cli &lt;command&gt; [options]

Příkazy:
  render     vykreslí položku projektu do PNG, SVG nebo PDF
  animate    vykreslí snímky animace položky (soubory PNG, MP4/GIF)
  analyse    vlastní čísla, kontraktivita, pevné body, dimenze (JSON)
  points     body F^k(X0) jako CSV
  check      ověří projektový soubor
  rewrite    načte a uloží projekt v kanonickém tvaru
  export     body atraktoru jako PLY, zjemněná síť nebo síť (v limitě) jako OBJ
  polygon    řídicí polygon po K krocích subdivize (JSON)
  import-mesh  soubor sítě (OBJ, OFF, PLY) jako projekt s položkou se sítí
  examples   vykreslí vestavěné obrázky z článků (000 Figs. 2, 3, 5) do PNG

Volby jednotlivých příkazů vypíše &apos;attractor-cli &lt;command&gt; --help&apos;.
</translation>
    </message>
    <message>
        <source>--out FILE (the project to write) is required</source>
        <translation>--out FILE (projekt, který se má zapsat) je povinné</translation>
    </message>
    <message>
        <source>The spectrum of the local subdivision matrix at an interior vertex of each valence: lambda (with its closed form), mu, lambda^2, Reif&apos;s C1 verdict and the curvature.</source>
        <translation>Spektrum lokální matice subdivize ve vnitřním vrcholu každé valence: lambda (s uzavřeným tvarem), mu, lambda^2, Reifův verdikt C1 a křivost.</translation>
    </message>
    <message>
        <source>catmull-clark (the default) or loop.</source>
        <translation>catmull-clark (výchozí) nebo loop.</translation>
    </message>
    <message>
        <source>The smallest valence (3 to 64, default 3).</source>
        <translation>Nejmenší valence (3 až 64, výchozí 3).</translation>
    </message>
    <message>
        <source>The largest valence (3 to 64, default 16).</source>
        <translation>Největší valence (3 až 64, výchozí 16).</translation>
    </message>
    <message>
        <source>Print JSON instead of a table.</source>
        <translation>Vypsat JSON místo tabulky.</translation>
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
        <translation type="vanished">Použití: attractor-cli &lt;command&gt; [options]

Příkazy:
  render     vykreslí položku projektu do PNG, SVG nebo PDF
  animate    vykreslí snímky animace položky (soubory PNG, MP4/GIF)
  analyse    vlastní čísla, kontraktivita, pevné body, dimenze (JSON)
  points     body F^k(X0) jako CSV
  check      ověří projektový soubor
  rewrite    načte a uloží projekt v kanonickém tvaru
  export     body atraktoru jako PLY, zjemněná síť nebo síť (v limitě) jako OBJ
  polygon    řídicí polygon po K krocích subdivize (JSON)
  import-mesh  soubor sítě (OBJ, OFF, PLY) jako projekt s položkou se sítí
  valences   lambda, mu, Reifův verdikt C1 pro každou valenci (Catmull-Clark, Loop)
  examples   vykreslí vestavěné obrázky z článků (000 Figs. 2, 3, 5) do PNG

Volby jednotlivých příkazů vypíše &apos;attractor-cli &lt;command&gt; --help&apos;.
</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation type="vanished">Exportuje geometrii položky: atraktor F^k(X0) jako mračno bodů PLY (u každého bodu s naposledy použitým zobrazením), síť plošné položky po k kolech klasické subdivize jako polygonovou síť OBJ, nebo položku se sítí po k krocích s každým vrcholem v jeho limitní poloze (OBJ); nebo její matice S_i, M_i, A_i jako pole buněk MATLABu pro JSR toolbox (matlab).</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh) or matlab (matrices).</source>
        <translation type="vanished">ply (body atraktoru), obj (zjemněná síť) nebo matlab (matice).</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|matlab and --out FILE are required</source>
        <translation type="vanished">--item NAME, --format ply|obj|matlab a --out FILE jsou povinné</translation>
    </message>
    <message>
        <source>--format must be ply, obj or matlab, got &apos;%1&apos;</source>
        <translation type="vanished">--format musí být ply, obj nebo matlab, zadáno „%1“</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); its maps as a Fractint .ifs entry (ifs); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation type="vanished">Exportuje geometrii položky: atraktor F^k(X0) jako mračno bodů PLY (u každého bodu s naposledy použitým zobrazením), síť plošné položky po k kolech klasické subdivize jako polygonovou síť OBJ, nebo položku se sítí po k krocích s každým vrcholem v jeho limitní poloze (OBJ); její zobrazení jako záznam souboru .ifs formátu Fractint (ifs); nebo její matice S_i, M_i, A_i jako pole buněk MATLABu pro JSR toolbox (matlab).</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh), ifs (Fractint) or matlab (matrices).</source>
        <translation type="vanished">ply (body atraktoru), obj (zjemněná síť), ifs (Fractint) nebo matlab (matice).</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|ifs|matlab and --out FILE are required</source>
        <translation type="vanished">--item NAME, --format ply|obj|ifs|matlab a --out FILE jsou povinné</translation>
    </message>
    <message>
        <source>--format must be ply, obj, ifs or matlab, got &apos;%1&apos;</source>
        <translation type="vanished">--format musí být ply, obj, ifs nebo matlab, zadáno „%1“</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit) as a fractal with control points.</source>
        <translation type="vanished">Vytvoří projekt ze souboru IFS jiného programu: každý záznam souboru .ifs formátu Fractint (2D i 3D; formát programů Fractint, xfractint a IFS Construction Kit) jako fraktál s řídicími body.</translation>
    </message>
    <message>
        <source>The file to import (.ifs).</source>
        <translation type="vanished">Soubor, který se má importovat (.ifs).</translation>
    </message>
    <message>
        <source>%1: import reads Fractint .ifs files</source>
        <translation type="vanished">%1: příkaz import čte soubory .ifs formátu Fractint</translation>
    </message>
    <message>
        <source>%1: no entry could be imported</source>
        <translation>%1: nepodařilo se importovat žádný záznam</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n item(s): %2
</source>
        <translation>
            <numerusform>%1: %n položka: %2
</numerusform>
            <numerusform>%1: %n položky: %2
</numerusform>
            <numerusform>%1: %n položek: %2
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
        <translation type="vanished">Použití: attractor-cli &lt;command&gt; [options]

Příkazy:
  render     vykreslí položku projektu do PNG, SVG nebo PDF
  animate    vykreslí snímky animace položky (soubory PNG, MP4/GIF)
  analyse    vlastní čísla, kontraktivita, pevné body, dimenze (JSON)
  points     body F^k(X0) jako CSV
  check      ověří projektový soubor
  rewrite    načte a uloží projekt v kanonickém tvaru
  export     body (PLY), řídicí nebo polygonová síť (OBJ), zobrazení (.ifs), matice (MATLAB)
  polygon    řídicí polygon po K krocích subdivize (JSON)
  import     soubor IFS jiného programu (Fractint .ifs) jako projekt
  import-mesh  soubor sítě (OBJ, OFF, PLY) jako projekt s položkou se sítí
  valences   lambda, mu, Reifův verdikt C1 pro každou valenci (Catmull-Clark, Loop)
  examples   vykreslí vestavěné obrázky z článků (000 Figs. 2, 3, 5) do PNG

Volby jednotlivých příkazů vypíše &apos;attractor-cli &lt;command&gt; --help&apos;.
</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); its maps as a Fractint .ifs entry (ifs) or a flam3 genome that flam3-render draws in the frame of render&apos;s --size and --bounds (flame); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation>Exportovat geometrii položky: atraktor F^k(X0) jako mračno bodů PLY (u každého bodu s naposledy použitým zobrazením), řídicí síť plošné položky po k krocích klasické subdivize jako síť OBJ, nebo síťovou položku po k krocích se všemi vrcholy v jejich limitní poloze (OBJ); její zobrazení jako záznam Fractint .ifs (ifs) nebo genom flam3, který flam3-render vykreslí v rámci daném volbami --size a --bounds příkazu render (flame); nebo její matice S_i, M_i, A_i jako pole buněk MATLABu pro JSR toolbox (matlab).</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh), ifs (Fractint), flame (flam3) or matlab (matrices).</source>
        <translation>ply (body atraktoru), obj (subdividovaná síť), ifs (Fractint), flame (flam3) nebo matlab (matice).</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|ifs|flame|matlab and --out FILE are required</source>
        <translation type="vanished">jsou vyžadovány --item NÁZEV, --format ply|obj|ifs|flame|matlab a --out SOUBOR</translation>
    </message>
    <message>
        <source>--format must be ply, obj, ifs, flame or matlab, got &apos;%1&apos;</source>
        <translation>--format musí být ply, obj, ifs, flame nebo matlab, zadáno „%1“</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has nothing to frame</source>
        <translation>„%1“ neobsahuje nic, co by šlo zarámovat</translation>
    </message>
    <message>
        <source>The output&apos;s format when its name has no suffix (e.g. /dev/stdout): png, svg, pdf or exr (default: the suffix).</source>
        <translation>Formát výstupu, pokud jeho název nemá příponu (např. /dev/stdout): png, svg, pdf nebo exr (výchozí: podle přípony).</translation>
    </message>
    <message>
        <source>PNG: 8 (the figure, default) or 16 (the attractor&apos;s raw density: alpha = log(1 + hits) / log(1 + most hits), the colour the hits&apos; mean; no title, polygons or margins). An .exr file always holds the raw density, as float32 counts.</source>
        <translation>PNG: 8 (obrázek, výchozí) nebo 16 (surová hustota atraktoru: alpha = log(1 + zásahy) / log(1 + max. zásahů), barva je průměrem zásahů; bez titulku, polygonů a okrajů). Soubor .exr vždy obsahuje surovou hustotu jako počty ve float32.</translation>
    </message>
    <message>
        <source>--format must be png, svg, pdf or exr, got &apos;%1&apos;</source>
        <translation>--format musí být png, svg, pdf nebo exr, zadáno „%1“</translation>
    </message>
    <message>
        <source>--bits must be 8 or 16, got &apos;%1&apos;</source>
        <translation>--bits musí být 8 nebo 16, zadáno „%1“</translation>
    </message>
    <message>
        <source>--bits 16 writes PNG files, got &apos;%1&apos;</source>
        <translation type="vanished">--bits 16 zapisuje soubory PNG, zadáno „%1“</translation>
    </message>
    <message>
        <source>the raw density (.exr, --bits 16) counts an attractor&apos;s points; this item&apos;s figure is a polygon</source>
        <translation type="vanished">surová hustota (.exr, --bits 16) počítá body atraktoru; obrázek této položky je polygon</translation>
    </message>
    <message>
        <source>the raw density (.exr, --bits 16) is of attractors drawn in the plane; &apos;%1&apos; is drawn in space</source>
        <translation type="vanished">surová hustota (.exr, --bits 16) je určena pro atraktory kreslené v rovině; „%1“ se kreslí v prostoru</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit), or every flame of a flam3 genome (.flame, .flam3: flam3, Apophysis, JWildfire), as a fractal with control points. Non-linear variations are dropped with a warning.</source>
        <translation type="vanished">Vytvořit projekt ze souboru IFS jiného nástroje: každý záznam souboru Fractint .ifs (2D i 3D, formát programů Fractint, xfractint a IFS Construction Kit) nebo každý plamen genomu flam3 (.flame, .flam3: flam3, Apophysis, JWildfire) se stane fraktálem s řídicími body. Nelineární variace se vynechají s varováním.</translation>
    </message>
    <message>
        <source>The file to import (.ifs, .flame, .flam3).</source>
        <translation>Soubor k importu (.ifs, .flame, .flam3).</translation>
    </message>
    <message>
        <source>%1: import reads Fractint .ifs and flam3 .flame (.flam3) files</source>
        <translation>%1: import čte soubory Fractint .ifs a flam3 .flame (.flam3)</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>varování: %1</translation>
    </message>
    <message>
        <source>Render an item&apos;s attractor (with its control polygons) to PNG, SVG or PDF; or its raw density (hits per pixel) to OpenEXR (.exr, float32 counts) or a 16-bit PNG (--bits 16), to tone-map elsewhere.</source>
        <translation>Vykreslit atraktor položky (s jejími řídicími polygony) do PNG, SVG nebo PDF; nebo jeho surovou hustotu (zásahy na pixel) do OpenEXR (.exr, počty ve float32) či do 16bitového PNG (--bits 16) pro mapování tónů jinde.</translation>
    </message>
    <message>
        <source>Output file: .png, .svg, .pdf or .exr.</source>
        <translation>Výstupní soubor: .png, .svg, .pdf nebo .exr.</translation>
    </message>
    <message>
        <source>With --item: write the certificate of the curve&apos;s exact Hölder exponent (verify-regularity checks it).</source>
        <translation>S --item: zapíše certifikát přesného Hölderova exponentu křivky (ověří jej verify-regularity).</translation>
    </message>
    <message>
        <source>--certificate needs --item: the certificate is one curve&apos;s</source>
        <translation>--certificate vyžaduje --item: certifikát patří vždy jedné křivce</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is not a subdivision curve: no regularity to certify</source>
        <translation>položka &apos;%1&apos; není subdivizní křivka: není co certifikovat</translation>
    </message>
    <message>
        <source>Where a curve scheme is C^k as one of its parameters moves: the parameter intervals on which the certified Hölder exponent exceeds k, each end bracketed by bisection on certified values.</source>
        <translation>Kde je schéma křivky třídy C^k, když se mění jeden z jeho parametrů: intervaly parametru, na nichž certifikovaný Hölderův exponent přesahuje k, přičemž každý konec je ohraničen bisekcí na certifikovaných hodnotách.</translation>
    </message>
    <message>
        <source>The project file (.awb).</source>
        <translation>Soubor projektu (.awb).</translation>
    </message>
    <message>
        <source>The curve item (default: the first item with an attractor).</source>
        <translation>Položka křivky (výchozí: první položka s atraktorem).</translation>
    </message>
    <message>
        <source>omega (four-point), a or b (corner cutting).</source>
        <translation type="vanished">omega (čtyřbodové schéma), a nebo b (ořezávání rohů).</translation>
    </message>
    <message>
        <source>The start of the range.</source>
        <translation>Začátek rozsahu.</translation>
    </message>
    <message>
        <source>The end of the range.</source>
        <translation>Konec rozsahu.</translation>
    </message>
    <message>
        <source>k: the class C^k asked for (default 1).</source>
        <translation>k: požadovaná třída C^k (výchozí 1).</translation>
    </message>
    <message>
        <source>Values of the first sweep, 2 to 10000 (default 24).</source>
        <translation>Počet hodnot prvního průchodu, 2 až 10000 (výchozí 24).</translation>
    </message>
    <message>
        <source>Bracket width at which bisection stops (default 1e-6).</source>
        <translation>Šířka intervalu, při které se bisekce zastaví (výchozí 1e-6).</translation>
    </message>
    <message>
        <source>Seconds of joint spectral radius per value (default 0.3).</source>
        <translation>Sekundy výpočtu společného spektrálního poloměru na jednu hodnotu (výchozí 0.3).</translation>
    </message>
    <message>
        <source>Print JSON instead of text.</source>
        <translation>Vypsat JSON místo textu.</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is not a subdivision curve: its scheme has no parameter to move</source>
        <translation>položka &apos;%1&apos; není subdivizní křivka: její schéma nemá žádný parametr, který by se dal měnit</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no parameter &apos;%3&apos;: omega belongs to the four-point scheme, a and b to corner cutting</source>
        <translation type="vanished">položka &apos;%1&apos; (%2) nemá parametr &apos;%3&apos;: omega patří ke čtyřbodovému schématu, a a b k ořezávání rohů</translation>
    </message>
    <message>
        <source>--from and --to are required</source>
        <translation>--from a --to jsou povinné</translation>
    </message>
    <message>
        <source>%1: C^%2 for %3 in %4 interval(s) of [%5, %6]</source>
        <translation>%1: C^%2 pro %3 v [%5, %6], počet intervalů: %4</translation>
    </message>
    <message>
        <source>%1 (the range&apos;s end)</source>
        <translation>%1 (konec rozsahu)</translation>
    </message>
    <message>
        <source>in [%1, %2]%3</source>
        <translation>v [%1, %2]%3</translation>
    </message>
    <message>
        <source> (the bounds cannot decide beyond)</source>
        <translation> (dále meze nerozhodnou)</translation>
    </message>
    <message>
        <source>  from %1 to %2</source>
        <translation>  od %1 do %2</translation>
    </message>
    <message>
        <source>%1 evaluations, %2 s</source>
        <translation>vyhodnocení: %1, %2 s</translation>
    </message>
    <message>
        <source>Re-check the certificate of an exact Hölder exponent, independently of the search that found it.</source>
        <translation>Znovu ověří certifikát přesného Hölderova exponentu, nezávisle na hledání, které jej našlo.</translation>
    </message>
    <message>
        <source>The certificate (.json).</source>
        <translation>Certifikát (.json).</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: larger than 64 MiB, not a certificate</source>
        <translation>%1: větší než 64 MiB, nejde o certifikát</translation>
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
        <translation type="vanished">Použití: attractor-cli &lt;příkaz&gt; [volby]

Příkazy:
  render     vykreslí položku projektu do PNG, SVG nebo PDF
  animate    vykreslí snímky animace položky (soubory PNG, MP4/GIF)
  analyse    vlastní čísla, kontraktivita, pevné body, dimenze (JSON)
  points     body F^k(X0) jako CSV
  check      ověří soubor projektu
  rewrite    načte a uloží projekt v kanonickém tvaru
  export     body (PLY), řídicí síť nebo síť (OBJ), zobrazení (.ifs), matice (MATLAB)
  polygon    řídicí polygon po K krocích subdivize (JSON)
  import     soubor IFS jiného nástroje (Fractint .ifs) jako projekt
  import-mesh  soubor sítě (OBJ, OFF, PLY) jako projekt s položkou sítě
  valences   lambda, mu, Reifův verdikt C1 pro každou valenci (Catmull-Clark, Loop)
  regularity-interval  kde je schéma třídy C^k při změně parametru
  verify-regularity  znovu ověří certifikát přesného Hölderova exponentu
  examples   vykreslí vestavěné obrázky z článku (000 obr. 2, 3, 5) do PNG

Volby příkazu vypíše &apos;attractor-cli &lt;příkaz&gt; --help&apos;.
</translation>
    </message>
    <message>
        <source>omega (four-point), a or b (corner cutting), or the name used in --mask.</source>
        <translation>omega (čtyřbodové schéma), a nebo b (ořezávání rohů), nebo jméno použité v --mask.</translation>
    </message>
    <message>
        <source>For a mask item: its coefficients with the parameter in them, e.g. &quot;-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w&quot;.</source>
        <translation>Pro položku s maskou: její koeficienty s parametrem, např. &quot;-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w&quot;.</translation>
    </message>
    <message>
        <source>--mask needs a mask item; &apos;%1&apos; is %2</source>
        <translation type="vanished">--mask vyžaduje položku s maskou; „%1“ je %2</translation>
    </message>
    <message>
        <source>the parameter of --mask must be a name that is not a function or constant (pi, e, sqrt, ...), got &apos;%1&apos;</source>
        <translation type="vanished">parametr --mask musí být jméno, které není funkcí ani konstantou (pi, e, sqrt, ...), zadáno „%1“</translation>
    </message>
    <message>
        <source>the mask &apos;%1&apos; does not contain the parameter &apos;%2&apos;</source>
        <translation type="vanished">maska „%1“ neobsahuje parametr „%2“</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no parameter &apos;%3&apos;: omega belongs to the four-point scheme, a and b to corner cutting; a mask item takes --mask with the parameter in its coefficients</source>
        <translation type="vanished">položka „%1“ (%2) nemá parametr „%3“: omega patří čtyřbodovému schématu, a a b ořezávání rohů; položka s maskou bere --mask s parametrem v koeficientech</translation>
    </message>
    <message>
        <source>the rendering was cancelled</source>
        <translation type="vanished">vykreslování bylo zrušeno</translation>
    </message>
    <message>
        <source>the project has no items</source>
        <translation>projekt neobsahuje žádné položky</translation>
    </message>
    <message>
        <source>no item called &quot;%1&quot;; the items: %2</source>
        <translation>žádná položka se nejmenuje „%1“; položky: %2</translation>
    </message>
    <message>
        <source>Set properties of an item and save the project (atomically: all of them or none), or list them. A value is typed as in the Properties dock: a number (3/8 and sqrt(3) too), a choice by its number, its word in the file or its text, true or false, a complex number as 0.5,0.3 or 0.5+0.3i; a structured value (points, matrices, a list) as JSON.</source>
        <translation>Nastaví vlastnosti položky a uloží projekt (atomicky: buď všechny, nebo žádnou), nebo je vypíše. Hodnota se zadává stejně jako v panelu Vlastnosti: číslo (i 3/8 a sqrt(3)), volba svým číslem, svým slovem v souboru nebo svým textem, true nebo false, komplexní číslo jako 0.5,0.3 nebo 0.5+0.3i; strukturovaná hodnota (body, matice, seznam) jako JSON.</translation>
    </message>
    <message>
        <source>Properties to set, in order.</source>
        <translation>Vlastnosti, které se mají nastavit, v daném pořadí.</translation>
    </message>
    <message>
        <source>The item (default: the first).</source>
        <translation>Položka (výchozí: první).</translation>
    </message>
    <message>
        <source>List the item&apos;s properties: key, type, value, range and choices.</source>
        <translation>Vypíše vlastnosti položky: klíč, typ, hodnotu, rozsah a možnosti volby.</translation>
    </message>
    <message>
        <source>With --list: as JSON.</source>
        <translation>S --list: jako JSON.</translation>
    </message>
    <message>
        <source>expected a project file; see --help</source>
        <translation>očekáván projektový soubor; viz --help</translation>
    </message>
    <message>
        <source>--list takes no key=value</source>
        <translation>--list nepřijímá žádné key=value</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>(shown, not set)</source>
        <translation>(jen zobrazeno, nelze nastavit)</translation>
    </message>
    <message>
        <source>nothing to set: give key=value (or --list)</source>
        <translation>není co nastavit: zadejte key=value (nebo --list)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not key=value</source>
        <translation>„%1“ nemá tvar key=value</translation>
    </message>
    <message>
        <source>render an item of a project to PNG, SVG or PDF</source>
        <translation>vykreslí položku projektu do PNG, SVG nebo PDF</translation>
    </message>
    <message>
        <source>render the frames of an item&apos;s animation (PNG files, MP4/GIF)</source>
        <translation>vykreslí snímky animace položky (soubory PNG, MP4/GIF)</translation>
    </message>
    <message>
        <source>eigenvalues, contractivity, fixed points, dimension (JSON)</source>
        <translation>vlastní čísla, kontraktivita, pevné body, dimenze (JSON)</translation>
    </message>
    <message>
        <source>the points of F^k(X0) as CSV</source>
        <translation>body F^k(X0) jako CSV</translation>
    </message>
    <message>
        <source>set an item&apos;s properties and save, or list them</source>
        <translation>nastaví vlastnosti položky a uloží projekt, nebo je vypíše</translation>
    </message>
    <message>
        <source>validate a project file</source>
        <translation>ověří soubor projektu</translation>
    </message>
    <message>
        <source>load and save a project in canonical form</source>
        <translation>načte a uloží projekt v kanonickém tvaru</translation>
    </message>
    <message>
        <source>points (PLY), a net or mesh (OBJ), maps (.ifs), matrices (MATLAB)</source>
        <translation>body (PLY), řídicí síť nebo síť (OBJ), zobrazení (.ifs), matice (MATLAB)</translation>
    </message>
    <message>
        <source>the control polygon after K subdivision steps (JSON)</source>
        <translation>řídicí polygon po K krocích subdivize (JSON)</translation>
    </message>
    <message>
        <source>another tool&apos;s IFS file (Fractint .ifs) as a project</source>
        <translation>soubor IFS jiného nástroje (Fractint .ifs) jako projekt</translation>
    </message>
    <message>
        <source>a mesh file (OBJ, OFF, PLY) as a project with a mesh item</source>
        <translation>soubor sítě (OBJ, OFF, PLY) jako projekt s položkou sítě</translation>
    </message>
    <message>
        <source>lambda, mu, Reif&apos;s C1 verdict per valence (Catmull-Clark, Loop)</source>
        <translation>lambda, mu, Reifův verdikt C1 pro každou valenci (Catmull-Clark, Loop)</translation>
    </message>
    <message>
        <source>where a scheme is C^k as a parameter moves</source>
        <translation>kde je schéma třídy C^k při změně parametru</translation>
    </message>
    <message>
        <source>re-check the certificate of an exact Hölder exponent</source>
        <translation>znovu ověří certifikát přesného Hölderova exponentu</translation>
    </message>
    <message>
        <source>render the built-in paper figures (000 Figs. 2, 3, 5) to PNG</source>
        <translation>vykreslí vestavěné obrázky z článku (000 obr. 2, 3, 5) do PNG</translation>
    </message>
    <message>
        <source>Usage: attractor-cli &lt;command&gt; [options]</source>
        <translation>Použití: attractor-cli &lt;příkaz&gt; [volby]</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>Příkazy:</translation>
    </message>
    <message>
        <source>Run &apos;attractor-cli &lt;command&gt; --help&apos; for the options of a command.</source>
        <translation>Volby příkazu vypíše &apos;attractor-cli &lt;příkaz&gt; --help&apos;.</translation>
    </message>
    <message>
        <source>%1: its %2 entries make a project of %3 MB, more than the %4 MB a project file may be</source>
        <translation>%1: jeho %2 položek dává projekt o %3 MB, více než %4 MB, které smí mít soubor projektu</translation>
    </message>
    <message>
        <source>%1: %2: note: its chaos game does not contract on average (the Lyapunov exponent along its orbit is %3): flam3 draws it by discarding the points that escape</source>
        <translation>%1: %2: poznámka: jeho chaos game nekontrahuje v průměru (Ljapunovův exponent podél jeho orbity je %3): flam3 ji kreslí tak, že zahazuje body, které uniknou</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit), or every flame of a flam3 genome (.flame, .flam3: flam3, Apophysis, JWildfire): a flame of affine maps as a fractal with control points, any other as a fractal flame item drawn by flam3&apos;s chaos game (a variation this program does not know is named in a warning).</source>
        <translation>Vytvoří projekt ze souboru IFS jiného programu: každý záznam souboru .ifs formátu Fractint (2D i 3D; formát programů Fractint, xfractint a IFS Construction Kit) nebo každý plamen genomu flam3 (.flame, .flam3: flam3, Apophysis, JWildfire): plamen z afinních zobrazení jako fraktál s řídicími body, každý jiný jako položka „fraktální plamen“, kterou kreslí hra chaosu programu flam3 (variace, kterou tento program nezná, je uvedena jménem ve varování).</translation>
    </message>
    <message>
        <source>attractor-cli: note: all %1 faces are triangles; --scheme loop keeps them triangles (Catmull-Clark makes each one three quads around a new valence-3 vertex)</source>
        <translation>attractor-cli: poznámka: všechny stěny (%1) jsou trojúhelníky; --scheme loop je zachová jako trojúhelníky (Catmull-Clark z každé udělá tři čtyřúhelníky kolem nového vrcholu valence 3)</translation>
    </message>
    <message>
        <source>A complex Bézier curve of t = 1/2 + iy in the scaled coordinates g(z, 1/(2y)) of 004 Thm 3.7.3, where it approaches the Takagi graph (the item&apos;s &quot;scaled&quot;, for this figure)</source>
        <translation>Komplexní Bézierova křivka pro t = 1/2 + iy ve škálovaných souřadnicích g(z, 1/(2y)) z 004 Thm 3.7.3, v nichž se blíží grafu Takagiho funkce (pro tento obrázek &quot;scaled&quot; položky)</translation>
    </message>
    <message>
        <source>--scaled draws a complex Bézier curve of t = 1/2 + iy (y ≠ 0) with control points on the real axis; &apos;%1&apos; is not one</source>
        <translation>--scaled vykresluje komplexní Bézierovu křivku pro t = 1/2 + iy (y ≠ 0) s řídicími body na reálné ose; &apos;%1&apos; taková není</translation>
    </message>
    <message>
        <source>attractor-cli: warning: %1</source>
        <translation>attractor-cli: varování: %1</translation>
    </message>
    <message>
        <source>  sharp features: %1 creases, %2 corners, %3 holes; boundary %4, crease method %5, triangles %6
</source>
        <translation>  ostré prvky: ostré hrany %1, rohy %2, díry %3; hranice %4, metoda ostrých hran %5, trojúhelníky %6
</translation>
    </message>
    <message>
        <source>Repair what is well defined before the checks: weld boundary vertices at the same position, turn flipped faces over, split vertices whose faces form several fans, name repeated vertices once; say each change.</source>
        <translation type="vanished">Před kontrolami opravit, co je jednoznačně definované: svařit hraniční vrcholy ve stejné poloze, otočit převrácené stěny, rozdělit vrcholy, jejichž stěny tvoří několik vějířů, opakované vrcholy uvést jen jednou; každou změnu vypsat.</translation>
    </message>
    <message>
        <source>repaired: %1</source>
        <translation>opraveno: %1</translation>
    </message>
    <message>
        <source>attractor-cli: not repaired: %1</source>
        <translation>attractor-cli: neopraveno: %1</translation>
    </message>
    <message>
        <source>repaired: nothing needed repair</source>
        <translation>opraveno: nebylo co opravovat</translation>
    </message>
    <message>
        <source> (--repair would weld %1 vertices, turn %2 faces over and split %3 vertices)</source>
        <translation type="vanished"> (--repair by svařil %1 vrcholů, otočil %2 stěn a rozdělil %3 vrcholů)</translation>
    </message>
    <message>
        <source>name repeated vertices once in %1 faces</source>
        <translation>uvést opakované vrcholy jen jednou v %1 stěnách</translation>
    </message>
    <message>
        <source>weld %1 vertices</source>
        <translation>svařit %1 vrcholů</translation>
    </message>
    <message>
        <source>turn %1 faces over</source>
        <translation>otočit %1 stěn</translation>
    </message>
    <message>
        <source>split %1 vertices</source>
        <translation>rozdělit %1 vrcholů</translation>
    </message>
    <message>
        <source> (--repair would %1)</source>
        <translation> (--repair by mohl %1)</translation>
    </message>
    <message>
        <source>Make a project of a mesh file (OBJ, OFF, PLY ASCII or binary): one subdivision-mesh item with the file&apos;s vertices, in its numbering, and its polygons. A non-manifold mesh (edges of three or more faces, faces of opposite orientations, vertices whose faces form several fans) is drawn as OpenSubdiv draws it, with a note.</source>
        <translation>Vytvoří projekt ze souboru sítě (OBJ, OFF, PLY ASCII nebo binární): jednu položku subdivizní sítě s vrcholy souboru v jeho číslování a s jeho polygony. Nevarietní síť (hrany tří a více stěn, stěny opačné orientace, vrcholy, jejichž stěny tvoří několik vějířů) se kreslí tak, jak ji kreslí OpenSubdiv, s poznámkou.</translation>
    </message>
    <message>
        <source>Repair what is well defined before the checks: weld boundary vertices at the same position, turn flipped faces over, split vertices whose faces form several fans, name repeated vertices once; say each change (the mesh is then drawn as the repaired surface, not as OpenSubdiv draws the original).</source>
        <translation>Před kontrolami opraví, co je dobře definované: svaří okrajové vrcholy na stejné pozici, otočí převrácené stěny, rozdělí vrcholy, jejichž stěny tvoří několik vějířů, opakované vrcholy uvede jednou; každou změnu oznámí (síť se pak kreslí jako opravená plocha, ne tak, jak OpenSubdiv kreslí původní).</translation>
    </message>
    <message>
        <source>attractor-cli: note: the mesh is %1%2</source>
        <translation>attractor-cli: poznámka: síť je %1%2</translation>
    </message>
    <message>
        <source>… (%1 in all)</source>
        <translation>… (celkem %1)</translation>
    </message>
    <message>
        <source>--item NAME is required: %1 has %2 items with an attractor: %3</source>
        <translation>--item NÁZEV je povinný: %1 má %2 položek s atraktorem: %3</translation>
    </message>
    <message>
        <source>The item (needed when the project has several).</source>
        <translation>Položka (nutná, má-li projekt více položek).</translation>
    </message>
    <message>
        <source>--format ply|obj|ifs|flame|matlab and --out FILE are required</source>
        <translation>--format ply|obj|ifs|flame|matlab a --out SOUBOR jsou povinné</translation>
    </message>
    <message>
        <source>Start set: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (plane coordinates; x,y,z for a surface) | lifted:x,y,c1,...;x,y,c1,... (points of the lifted space of 000 §2) | net:i,j,... (control points by index, from 0: the rows of the lifted P) | vertex-limits (a mesh item: the limit positions of the vertices of the mesh refined k times; default: the item&apos;s).</source>
        <translation>Počáteční množina: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (rovinné souřadnice; u plochy x,y,z) | lifted:x,y,c1,...;x,y,c1,... (body zdviženého prostoru z 000 §2) | net:i,j,... (řídicí body podle indexu od 0: řádky zdvižené matice P) | vertex-limits (položka se sítí: limitní polohy vrcholů sítě zjemněné k-krát; výchozí: podle položky).</translation>
    </message>
    <message>
        <source>%1: %2 % (%3 s</source>
        <translation>%1: %2 % (%3 s</translation>
    </message>
    <message>
        <source>, about %1 s left</source>
        <translation>, zbývá asi %1 s</translation>
    </message>
    <message>
        <source>Report the iteration&apos;s progress on stderr, one line per report (default: on a terminal only, after a second).</source>
        <translation>Hlásit průběh iterace na stderr, jeden řádek na hlášení (výchozí: jen na terminálu, po první sekundě).</translation>
    </message>
</context>
<context>
    <name>awb::core</name>
    <message>
        <source>%1: entry (row %2, column %3) is not a finite number</source>
        <translation>%1: prvek (řádek %2, sloupec %3) není konečné číslo</translation>
    </message>
    <message>
        <source>matrix rows of different lengths</source>
        <translation>řádky matice mají různé délky</translation>
    </message>
</context>
<context>
    <name>awb::exchange</name>
    <message>
        <source>%1, line %2, column %3</source>
        <translation>%1, řádek %2, sloupec %3</translation>
    </message>
    <message>
        <source>: entry %1</source>
        <translation>: záznam %1</translation>
    </message>
    <message>
        <source>a &apos;}&apos; without its &apos;{&apos;</source>
        <translation>„}“ bez odpovídající „{“</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not followed by &apos;{&apos;: an entry is NAME { rows }</source>
        <translation>za „%1“ nenásleduje „{“: záznam má tvar NAME { rows }</translation>
    </message>
    <message>
        <source>entry at line %1</source>
        <translation>záznam na řádku %1</translation>
    </message>
    <message>
        <source>a &apos;{&apos; inside an entry: its &apos;}&apos; is missing</source>
        <translation>„{“ uvnitř záznamu: chybí jeho „}“</translation>
    </message>
    <message>
        <source>the file ends before the entry&apos;s &apos;}&apos;</source>
        <translation>soubor končí před „}“ záznamu</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a finite number</source>
        <translation>„%1“ není konečné číslo</translation>
    </message>
    <message>
        <source>the entry has no maps</source>
        <translation>záznam nemá žádná zobrazení</translation>
    </message>
    <message>
        <source>%1 numbers: a %2D entry has rows of %3 (the map&apos;s coefficients, then its probability), %4 left over</source>
        <translation>počet čísel: %1; záznam %2D má řádky po %3 číslech (koeficienty zobrazení a za nimi jeho pravděpodobnost), přebývá %4</translation>
    </message>
    <message>
        <source>map %1 has the negative probability %2</source>
        <translation>zobrazení %1 má zápornou pravděpodobnost %2</translation>
    </message>
    <message>
        <source>a Fractint entry holds maps of the plane or of space, not of dimension %1</source>
        <translation>záznam formátu Fractint obsahuje zobrazení roviny nebo prostoru, ne dimenze %1</translation>
    </message>
    <message>
        <source>the entry&apos;s maps are not all of its dimension</source>
        <translation>ne všechna zobrazení záznamu mají jeho dimenzi</translation>
    </message>
    <message>
        <source>entry %1: random iteration leaves every bound (its maps do not contract)</source>
        <translation>záznam %1: náhodná iterace překračuje všechny meze (jeho zobrazení nejsou kontrakce)</translation>
    </message>
    <message>
        <source>the row starting here runs on to the next line: a %1D entry has rows of %2 numbers (the map&apos;s coefficients, then its probability), one row per line</source>
        <translation>řádek čísel začínající zde pokračuje na dalším řádku: položka %1D má řádky po %2 číslech (koeficienty zobrazení, pak jeho pravděpodobnost), jeden řádek na řádce</translation>
    </message>
    <message>
        <source>%1 maps: at most %2 maps are supported</source>
        <translation>%1 zobrazení: podporováno je nejvýše %2 zobrazení</translation>
    </message>
    <message>
        <source>the probabilities sum to %1, not 1: they are used as relative weights</source>
        <translation>pravděpodobnosti mají součet %1, ne 1: použijí se jako relativní váhy</translation>
    </message>
    <message>
        <source>the probabilities are all 0: the maps are chosen with equal probabilities</source>
        <translation>všechny pravděpodobnosti jsou 0: zobrazení se volí se stejnými pravděpodobnostmi</translation>
    </message>
    <message>
        <source>a file of bare rows (Fractint 10 and 15: one IFS, no NAME { }) has rows of 7 (2D) or 13 (3D) numbers, its first line %1</source>
        <translation>soubor holých řádků (Fractint 10 a 15: jeden IFS, bez NÁZEV { }) má řádky po 7 (2D) nebo 13 (3D) číslech, jeho první řádek %1</translation>
    </message>
    <message>
        <source>a file of bare rows (Fractint 10 and 15) has no braces: an entry is NAME { rows } throughout</source>
        <translation>soubor holých řádků (Fractint 10 a 15) nemá složené závorky: jinak je každá položka NÁZEV { řádky }</translation>
    </message>
    <message>
        <source>%1 more problems</source>
        <translation>%1 dalších problémů</translation>
    </message>
    <message>
        <source>%1 more entries after the first %2: one file gives at most %2</source>
        <translation>%1 dalších položek po prvních %2: jeden soubor dává nejvýše %2</translation>
    </message>
    <message>
        <source>%1 more warnings</source>
        <translation>%1 dalších varování</translation>
    </message>
</context>
<context>
    <name>awb::flame</name>
    <message>
        <source>%1: a coefficient is not a finite number</source>
        <translation>%1: koeficient není konečné číslo</translation>
    </message>
    <message>
        <source>%1: variation %2 does not exist</source>
        <translation>%1: variace %2 neexistuje</translation>
    </message>
    <message>
        <source>%1: the weight of variation %2 is not a finite number</source>
        <translation>%1: váha variace %2 není konečné číslo</translation>
    </message>
    <message>
        <source>%1: its variation parameters are incomplete</source>
        <translation>%1: jeho parametry variací jsou neúplné</translation>
    </message>
    <message>
        <source>%1: parameter %2 is not a finite number</source>
        <translation>%1: parametr %2 není konečné číslo</translation>
    </message>
    <message>
        <source>%1: its colour, colour speed or opacity is not a finite number</source>
        <translation>%1: jeho barva, rychlost barvy nebo neprůhlednost není konečné číslo</translation>
    </message>
    <message>
        <source>the flame has no xform</source>
        <translation>plamen nemá žádný xform</translation>
    </message>
    <message>
        <source>the flame has %1 xforms; at most %2 are drawn</source>
        <translation>plamen má %1 xforms; kreslí se nejvýše %2</translation>
    </message>
    <message>
        <source>xform %1</source>
        <translation>xform %1</translation>
    </message>
    <message>
        <source>%1: its weight %2 is not a number &gt;= 0</source>
        <translation>%1: jeho váha %2 není číslo &gt;= 0</translation>
    </message>
    <message>
        <source>%1: its xaos row has %2 entries for %3 xforms</source>
        <translation>%1: jeho řádek xaos má %2 položek pro %3 xforms</translation>
    </message>
    <message>
        <source>%1: a xaos entry is not a number &gt;= 0</source>
        <translation>%1: položka xaos není číslo &gt;= 0</translation>
    </message>
    <message>
        <source>every xform of the flame has weight 0: none is ever chosen</source>
        <translation>každý xform plamene má váhu 0: žádný se nikdy nevybere</translation>
    </message>
    <message>
        <source>xform %1: its xaos row forbids every xform, so an orbit that reaches it cannot go on</source>
        <translation>xform %1: jeho řádek xaos zakazuje všechny xforms, takže orbita, která jej dosáhne, nemůže pokračovat</translation>
    </message>
    <message>
        <source>the final xform</source>
        <translation>závěrečný xform</translation>
    </message>
    <message>
        <source>there is no flame to draw</source>
        <translation>není co kreslit: chybí plamen</translation>
    </message>
    <message>
        <source>the spatial filter of radius %1 at supersample %2 would be %3 cells wide; at most %4</source>
        <translation>prostorový filtr poloměru %1 při převzorkování %2 by měl šířku %3 buněk; nejvýše %4</translation>
    </message>
    <message>
        <source>the spatial filter of radius %1 is too small</source>
        <translation>prostorový filtr poloměru %1 je příliš malý</translation>
    </message>
    <message>
        <source>the estimator curve must be &gt; 0</source>
        <translation>křivka odhadu musí být &gt; 0</translation>
    </message>
    <message>
        <source>the estimator radius %1 must be at least its minimum %2 (and not negative)</source>
        <translation>poloměr odhadu %1 musí být alespoň jeho minimum %2 (a nezáporný)</translation>
    </message>
    <message>
        <source>the estimator (radius %1, minimum %2, curve %3) needs too many kernels (%4)</source>
        <translation>odhad (poloměr %1, minimum %2, křivka %3) potřebuje příliš mnoho jader (%4)</translation>
    </message>
    <message>
        <source>the estimator of radius %1 at supersample %2 needs %3 coefficients; at most %4</source>
        <translation>odhad poloměru %1 při převzorkování %2 potřebuje %3 koeficientů; nejvýše %4</translation>
    </message>
    <message>
        <source>a %1 x %2 picture of the flame at supersample %3 needs %4 x %5 histogram cells; at most 32768 a side</source>
        <translation>obraz plamene %1 x %2 při převzorkování %3 potřebuje %4 x %5 buněk histogramu; nejvýše 32768 na stranu</translation>
    </message>
    <message>
        <source>a %1 x %2 picture of the flame at supersample %3 needs %4 MB of histograms; at most %5 MB</source>
        <translation>obraz plamene %1 x %2 při převzorkování %3 potřebuje %4 MB histogramů; nejvýše %5 MB</translation>
    </message>
    <message>
        <source>the flame&apos;s passes is %1; it takes 1 to %2</source>
        <translation>počet průchodů plamene je %1; povoleno je 1 až %2</translation>
    </message>
</context>
<context>
    <name>awb::flame::MakeSink</name>
    <message>
        <source>there is no flame to draw</source>
        <translation>není co kreslit: chybí plamen</translation>
    </message>
</context>
<context>
    <name>awb::ifs</name>
    <message>
        <source>the IFS has 1 map (0)</source>
        <translation>IFS má 1 zobrazení (0)</translation>
    </message>
    <message>
        <source>the IFS has %1 maps (0..%2)</source>
        <translation>IFS má %1 zobrazení (0..%2)</translation>
    </message>
    <message>
        <source>no parameter intervals</source>
        <translation>žádné intervaly parametru</translation>
    </message>
    <message>
        <source>a parameter interval is empty or not finite</source>
        <translation>interval parametru je prázdný nebo není konečný</translation>
    </message>
    <message>
        <source>the address has %1 symbols, more than %2</source>
        <translation>počet symbolů adresy (%1) je větší než %2</translation>
    </message>
    <message>
        <source>symbol %1 of the address is map %2, but %3</source>
        <translation>symbol %1 adresy je zobrazení %2, ale %3</translation>
    </message>
    <message>
        <source>the IFS has no maps</source>
        <translation>IFS nemá žádná zobrazení</translation>
    </message>
    <message>
        <source>the address &apos;%1&apos; has an empty symbol (a comma too many)</source>
        <translation>adresa „%1“ obsahuje prázdný symbol (čárka navíc)</translation>
    </message>
    <message>
        <source>the address &apos;%1&apos; ends with a comma</source>
        <translation>adresa „%1“ končí čárkou</translation>
    </message>
    <message>
        <source>the address is empty: give map numbers such as 0,1,1</source>
        <translation>adresa je prázdná: zadejte čísla zobrazení, např. 0,1,1</translation>
    </message>
    <message>
        <source>symbol %1 of the address, &apos;%2&apos;, is not a map number (0-based whole number)</source>
        <translation>symbol %1 adresy, „%2“, není číslo zobrazení (celé číslo od 0)</translation>
    </message>
    <message>
        <source>no subdivision matrices</source>
        <translation>žádné subdivizní matice</translation>
    </message>
    <message>
        <source>the subdivision matrices differ in size</source>
        <translation>subdivizní matice mají různé rozměry</translation>
    </message>
    <message>
        <source>the parameter %1 is outside [0, 1]</source>
        <translation>parametr %1 leží mimo [0, 1]</translation>
    </message>
    <message>
        <source>an address has 0..%1 symbols</source>
        <translation>adresa má 0..%1 symbolů</translation>
    </message>
    <message>
        <source>the parameter interval must satisfy 0 &lt;= t0 &lt; t1 &lt;= 1</source>
        <translation>interval parametru musí splňovat 0 &lt;= t0 &lt; t1 &lt;= 1</translation>
    </message>
    <message>
        <source>the seed point has %1 coordinates, the IFS %2</source>
        <translation>zárodečný bod má počet souřadnic %1, IFS %2</translation>
    </message>
    <message>
        <source>map 0 does not converge to a fixed point</source>
        <translation>zobrazení 0 nekonverguje k pevnému bodu</translation>
    </message>
    <message>
        <source>iteration depth must be between 0 and %1, got %2</source>
        <translation>hloubka iterace musí být mezi 0 a %1, zadáno %2</translation>
    </message>
    <message>
        <source>the start set is empty</source>
        <translation>počáteční množina je prázdná</translation>
    </message>
    <message>
        <source>start set has %1 coordinates, the IFS space has %2</source>
        <translation>počáteční množina má počet souřadnic %1, prostor IFS má %2</translation>
    </message>
    <message>
        <source>start set</source>
        <translation>počáteční množina</translation>
    </message>
    <message>
        <source>at most 255 maps are supported, got %1</source>
        <translation type="vanished">podporováno je nejvýše 255 zobrazení, zadáno %1</translation>
    </message>
    <message>
        <source>no sink to receive the attractor</source>
        <translation>chybí cíl, který by přijal atraktor</translation>
    </message>
    <message>
        <source>start point has %1 coordinates, the IFS space has %2</source>
        <translation>počáteční bod má počet souřadnic %1, prostor IFS má %2</translation>
    </message>
    <message>
        <source>start point</source>
        <translation>počáteční bod</translation>
    </message>
    <message>
        <source>at most %1 random-iteration samples, got %2</source>
        <translation>nejvýše %1 vzorků náhodné iterace, zadáno %2</translation>
    </message>
    <message>
        <source>column %1 of %2 sums to %3, not 1: it does not map barycentric points to barycentric points</source>
        <translation>součet sloupce %1 matice %2 je %3, nikoli 1: nezobrazuje barycentrické body na barycentrické body</translation>
    </message>
    <message>
        <source>the BCIFS has no cell &apos;%1&apos;</source>
        <translation>BCIFS nemá buňku „%1“</translation>
    </message>
    <message>
        <source>the BCIFS has no operator &apos;%1&apos;</source>
        <translation>BCIFS nemá operátor „%1“</translation>
    </message>
    <message>
        <source>the BCIFS has no cells</source>
        <translation>BCIFS nemá žádné buňky</translation>
    </message>
    <message>
        <source>cell &apos;%1&apos; has dimension %2; it needs at least one control point</source>
        <translation>buňka „%1“ má dimenzi %2; potřebuje alespoň jeden řídicí bod</translation>
    </message>
    <message>
        <source>operator &apos;%1&apos; joins a cell that does not exist</source>
        <translation>operátor „%1“ spojuje buňku, která neexistuje</translation>
    </message>
    <message>
        <source>operator &apos;%1&apos; (%2 -&gt; %3)</source>
        <translation>operátor „%1“ (%2 -&gt; %3)</translation>
    </message>
    <message>
        <source>%1 joins cells of the wrong kinds: subdivisions join edges or vertices, boundary operators go from an edge to a vertex, placements from the model</source>
        <translation>%1 spojuje buňky nesprávných druhů: subdivize spojují hrany nebo vrcholy, hraniční operátory vedou z hrany do vrcholu, umístění z modelu</translation>
    </message>
    <message>
        <source>%1 is %2; it must be %3 x %4 (column convention: rows = dimension of &apos;%5&apos;, columns = dimension of &apos;%6&apos;)</source>
        <translation>%1 má rozměr %2; musí mít rozměr %3 x %4 (sloupcová konvence: řádky = dimenze „%5“, sloupce = dimenze „%6“)</translation>
    </message>
    <message>
        <source>edge cell &apos;%1&apos; has no subdivision operator: its attractor would be empty</source>
        <translation>hranová buňka „%1“ nemá subdivizní operátor: její atraktor by byl prázdný</translation>
    </message>
    <message>
        <source>constraint %1</source>
        <translation>podmínka %1</translation>
    </message>
    <message>
        <source>%1 has an empty side or an unknown operator</source>
        <translation>%1 má prázdnou stranu nebo neznámý operátor</translation>
    </message>
    <message>
        <source>%1: %2 ends at &apos;%3&apos; but %4 starts at &apos;%5&apos;</source>
        <translation>%1: %2 končí v „%3“, ale %4 začíná v „%5“</translation>
    </message>
    <message>
        <source>%1 (%2) compares paths between different cells</source>
        <translation>%1 (%2) porovnává cesty mezi různými buňkami</translation>
    </message>
    <message>
        <source>%1 constraint %2 %3 is violated by %4 (entry row %5, column %6)</source>
        <translation>podmínka %2 typu %1 %3 je porušena o %4 (prvek v řádku %5, sloupci %6)</translation>
    </message>
    <message>
        <source>; also violated:</source>
        <translation>; porušeny jsou také:</translation>
    </message>
    <message>
        <source>edge cell &apos;%1&apos; has no placement (control points): it cannot be drawn</source>
        <translation>hranová buňka „%1“ nemá umístění (řídicí body): nelze ji vykreslit</translation>
    </message>
    <message>
        <source>the junction matrix must be square and at least 2 x 2, got %1</source>
        <translation>matice napojení musí být čtvercová a alespoň 2 x 2, zadáno %1</translation>
    </message>
    <message>
        <source>the copy&apos;s placement must have %1 rows (one per control point of the junction), got %2</source>
        <translation>umístění kopie musí mít počet řádků %1 (jeden na každý řídicí bod napojení), zadáno %2</translation>
    </message>
    <message>
        <source>the junction has %1 control points, got %2</source>
        <translation>napojení má počet řídicích bodů %1, zadáno %2</translation>
    </message>
    <message>
        <source>junction matrix</source>
        <translation>matice napojení</translation>
    </message>
    <message>
        <source>copy placement</source>
        <translation>umístění kopie</translation>
    </message>
    <message>
        <source>the junction matrix</source>
        <translation>matice napojení</translation>
    </message>
    <message>
        <source>the copy placement</source>
        <translation>umístění kopie</translation>
    </message>
    <message>
        <source>the copies collapse onto the fixed point: no tangent information</source>
        <translation>kopie se smršťují do pevného bodu: žádná informace o tečně</translation>
    </message>
    <message>
        <source>lambda = %1: %2</source>
        <translation>lambda = %1: %2</translation>
    </message>
    <message>
        <source>; |lambda| &gt;= 1, so the junction matrix does not contract</source>
        <translation>; |lambda| &gt;= 1, takže matice napojení není kontrakce</translation>
    </message>
    <message>
        <source> (the copy has no component along the subdominant eigenvector, lambda = %1, so the next eigenvalue governs)</source>
        <translation> (kopie nemá žádnou složku ve směru subdominantního vlastního vektoru, lambda = %1, takže rozhoduje další vlastní číslo)</translation>
    </message>
    <message>
        <source> (the eigenvectors are not complete; the copy&apos;s components were not examined)</source>
        <translation> (vlastní vektory netvoří úplný systém; složky kopie nebyly zkoumány)</translation>
    </message>
    <message>
        <source>vertex subdivisions must be square and non-empty, got %1 and %2</source>
        <translation>subdivize vrcholů musí být čtvercové a neprázdné, zadáno %1 a %2</translation>
    </message>
    <message>
        <source>the free columns must have %1 rows (n_l + n_r), got X %2 and Y %3</source>
        <translation>volné sloupce musí mít počet řádků %1 (n_l + n_r), zadáno X %2 a Y %3</translation>
    </message>
    <message>
        <source>free columns X of T^l</source>
        <translation>volné sloupce X matice T^l</translation>
    </message>
    <message>
        <source>free columns Y of T^r</source>
        <translation>volné sloupce Y matice T^r</translation>
    </message>
    <message>
        <source>the free columns X of T^l</source>
        <translation>volné sloupce X matice T^l</translation>
    </message>
    <message>
        <source>the free columns Y of T^r</source>
        <translation>volné sloupce Y matice T^r</translation>
    </message>
    <message>
        <source>the %1 curve&apos;s subdivision operators must both be m x m, got %2 and %3</source>
        <translation>subdivizní operátory křivky %1 musí být oba m x m, zadáno %2 a %3</translation>
    </message>
    <message>
        <source>the %1 curve&apos;s vertex dimension must be in 1..%2, got %3</source>
        <translation>dimenze vrcholů křivky %1 musí být v rozmezí 1..%2, zadáno %3</translation>
    </message>
    <message>
        <source>the %1 curve needs %2 control points, got %3</source>
        <translation>počet řídicích bodů křivky %1 musí být %2, zadáno %3</translation>
    </message>
    <message>
        <source>control points of the %1 curve</source>
        <translation>řídicí body křivky %1</translation>
    </message>
    <message>
        <source>both curves&apos; control points must have the same dimension</source>
        <translation>řídicí body obou křivek musí mít stejnou dimenzi</translation>
    </message>
    <message>
        <source>X must have m_l - n_l columns and Y m_r - n_r</source>
        <translation>X musí mít m_l - n_l sloupců a Y m_r - n_r</translation>
    </message>
    <message>
        <source>junction parameter %1 is not a finite number</source>
        <translation>parametr napojení %1 není konečné číslo</translation>
    </message>
    <message>
        <source>T^i has no subdominant eigenvalue</source>
        <translation>T^i nemá subdominantní vlastní číslo</translation>
    </message>
    <message>
        <source>lambda_2 = %1 (%2)</source>
        <translation>lambda_2 = %1 (%2)</translation>
    </message>
    <message>
        <source>: |lambda_2| &gt;= 1, T^i does not contract and the junction does not converge</source>
        <translation>: |lambda_2| &gt;= 1, T^i není kontrakce a napojení nekonverguje</translation>
    </message>
    <message>
        <source>: both sides have half-tangents along the same eigenvector, from opposite sides: G1 at the junction point</source>
        <translation>: obě strany mají poloteče podél stejného vlastního vektoru, z opačných stran: v bodě napojení je G1</translation>
    </message>
    <message>
        <source>: both sides have half-tangents, but they are not opposite (a corner or cusp)</source>
        <translation>: obě strany mají poloteče, ale nejsou opačné (roh nebo hrot)</translation>
    </message>
    <message>
        <source>the cubic needs 4 and the quadratic 3 control points of one dimension, got %1 and %2</source>
        <translation>kubika vyžaduje 4 a kvadratika 3 řídicí body stejné dimenze, zadáno %1 a %2</translation>
    </message>
    <message>
        <source>%1 must exceed the other eigenvalues of %2 (largest modulus %3) to be subdominant, and be below 1 for %2 to contract</source>
        <translation>%1 musí převyšovat ostatní vlastní čísla matice %2 (největší absolutní hodnota %3), aby bylo subdominantní, a být menší než 1, aby %2 byla kontrakce</translation>
    </message>
    <message>
        <source>refined junction parameter %1 is not a finite number</source>
        <translation>parametr zjemněného napojení %1 není konečné číslo</translation>
    </message>
    <message>
        <source>refined junction parameter %1 = %2 is outside its admissible range (%3, %4): %5</source>
        <translation>parametr zjemněného napojení %1 = %2 leží mimo svůj přípustný rozsah (%3, %4): %5</translation>
    </message>
    <message>
        <source>the refined junction needs 4 cubic, 3 quadratic and 3 handle control points of one dimension, got %1, %2 and %3</source>
        <translation>zjemněné napojení vyžaduje 4 kubické, 3 kvadratické a 3 úchytové řídicí body stejné dimenze, zadáno %1, %2 a %3</translation>
    </message>
    <message>
        <source>handles of the refined junction</source>
        <translation>úchyty zjemněného napojení</translation>
    </message>
    <message>
        <source>the split parameter u is not a finite number</source>
        <translation>parametr dělení u není konečné číslo</translation>
    </message>
    <message>
        <source>the split parameter u = %1 must lie strictly between 0 and 1 (002 §4: 0 &lt; u &lt; 1)</source>
        <translation>parametr dělení u = %1 musí ležet ostře mezi 0 a 1 (002 §4: 0 &lt; u &lt; 1)</translation>
    </message>
    <message>
        <source>coincide</source>
        <comment>points</comment>
        <translation>splývají</translation>
    </message>
    <message>
        <source>are collinear</source>
        <comment>points</comment>
        <translation>leží na jedné přímce</translation>
    </message>
    <message>
        <source>are coplanar</source>
        <comment>points</comment>
        <translation>leží v jedné rovině</translation>
    </message>
    <message>
        <source>the affine map is not invertible (its linear part is singular)</source>
        <translation>afinní zobrazení není invertibilní (jeho lineární část je singulární)</translation>
    </message>
    <message>
        <source>an affine map of R^%1 is fixed by %2 point pairs</source>
        <translation>afinní zobrazení R^%1 je určeno %2 dvojicemi bodů</translation>
    </message>
    <message>
        <source>source points</source>
        <translation>zdrojové body</translation>
    </message>
    <message>
        <source>target points</source>
        <translation>cílové body</translation>
    </message>
    <message>
        <source>the source points %1: no unique affine map takes them to the targets</source>
        <translation>zdrojové body %1: žádné jednoznačné afinní zobrazení je nepřevádí na cílové body</translation>
    </message>
    <message>
        <source>fractal interpolation needs N + 1 &gt;= 3 data points (x, y)</source>
        <translation>fraktální interpolace vyžaduje N + 1 &gt;= 3 datových bodů (x, y)</translation>
    </message>
    <message>
        <source>interpolation data</source>
        <translation>interpolační data</translation>
    </message>
    <message>
        <source>fractal interpolation through %1 points needs %2 vertical scalings d_n, got %3</source>
        <translation>fraktální interpolace procházející %1 body vyžaduje počet svislých škálovacích faktorů d_n %2, zadáno %3</translation>
    </message>
    <message>
        <source>interpolation abscissae must increase (x_%1 &lt;= x_%2)</source>
        <translation>x-ové souřadnice interpolačních bodů musí být rostoucí (x_%1 &lt;= x_%2)</translation>
    </message>
    <message>
        <source>vertical scaling d_%1 = %2 must satisfy |d_n| &lt; 1</source>
        <translation>svislý škálovací faktor d_%1 = %2 musí splňovat |d_n| &lt; 1</translation>
    </message>
    <message>
        <source>002 §5 needs three control points in the plane (3 x 2)</source>
        <translation>002 §5 vyžaduje tři řídicí body v rovině (3 x 2)</translation>
    </message>
    <message>
        <source>control points</source>
        <translation>řídicí body</translation>
    </message>
    <message>
        <source>control points Q0, Q1, Q2 are collinear: the map omega of 002 §5 is not invertible</source>
        <translation>řídicí body Q0, Q1, Q2 leží na jedné přímce: zobrazení omega z 002 §5 není invertibilní</translation>
    </message>
    <message>
        <source>a Bézier curve needs at least 2 control points (degree &gt;= 1), got %1</source>
        <translation>Bézierova křivka vyžaduje alespoň 2 řídicí body (stupeň &gt;= 1), zadáno %1</translation>
    </message>
    <message>
        <source>control points must have 1 to 3 coordinates</source>
        <translation>řídicí body musí mít 1 až 3 souřadnice</translation>
    </message>
    <message>
        <source>the %1 control points %2, so the affine maps of eqs. (9)-(10) are not unique</source>
        <translation>řídicí body (%1) %2, takže afinní zobrazení z eqs. (9)-(10) nejsou jednoznačná</translation>
    </message>
    <message>
        <source>no affine map of R^%1 takes the control polygon of this degree-%2 curve to its de Casteljau pieces (mismatch %3): the pieces are not affine images of the curve in its own space</source>
        <translation>žádné afinní zobrazení R^%1 nepřevádí řídicí polygon této křivky stupně %2 na její de Casteljauovy části (odchylka %3): části nejsou afinními obrazy křivky v jejím vlastním prostoru</translation>
    </message>
    <message>
        <source>; the maps act on barycentric coordinates R^%1 (%2)</source>
        <translation>; zobrazení působí na barycentrických souřadnicích R^%1 (%2)</translation>
    </message>
    <message>
        <source>; the maps act on the lifted space R^%1 of 000 §2, drawn through its first %2 coordinates</source>
        <translation>; zobrazení působí na zdviženém prostoru R^%1 z 000 §2, který se kreslí pomocí jeho prvních %2 souřadnic</translation>
    </message>
    <message>
        <source>map 1 has spectral radius %1, map 2 %2; %3 levels shrink every piece to 1/1000 of the curve</source>
        <translation>zobrazení 1 má spektrální poloměr %1, zobrazení 2 %2; po %3 úrovních se každá část zmenší na 1/1000 křivky</translation>
    </message>
    <message>
        <source>. u = %1 is close to %2: map %3 is nearly non-contractive and the pieces are very unequal (random iteration, or u nearer 1/2, converges faster)</source>
        <translation>. u = %1 je blízko %2: zobrazení %3 je téměř nekontraktivní a části jsou velmi nestejné (náhodná iterace nebo u blíže 1/2 konverguje rychleji)</translation>
    </message>
    <message>
        <source>. Map %1 is not a Euclidean contraction (||A||_2 = %2) but is eventually contractive, as 002 §5 allows</source>
        <translation>. Zobrazení %1 není eukleidovská kontrakce (||A||_2 = %2), ale je eventuálně kontraktivní, jak 002 §5 připouští</translation>
    </message>
    <message>
        <source>a combined IFS needs at least one curve</source>
        <translation>kombinovaný IFS vyžaduje alespoň jednu křivku</translation>
    </message>
    <message>
        <source>curve %1</source>
        <translation>křivka %1</translation>
    </message>
    <message>
        <source>%1: the combined IFS of 002 §6 acts on the plane, control points need 2 coordinates</source>
        <translation>%1: kombinovaný IFS z 002 §6 působí v rovině, řídicí body musí mít 2 souřadnice</translation>
    </message>
    <message>
        <source>%1: its maps do not act on the plane (%2), so they cannot be combined with the other curves&apos; maps</source>
        <translation>%1: její zobrazení nepůsobí v rovině (%2), takže je nelze kombinovat se zobrazeními ostatních křivek</translation>
    </message>
    <message>
        <source>a union needs at least one curve</source>
        <translation>sjednocení vyžaduje alespoň jednu křivku</translation>
    </message>
    <message>
        <source>arc &apos;%1&apos; (%2 -&gt; %3)</source>
        <translation>hrana „%1“ (%2 -&gt; %3)</translation>
    </message>
    <message>
        <source>the automaton has no states</source>
        <translation>automat nemá žádné stavy</translation>
    </message>
    <message>
        <source>state &apos;%1&apos; has no control points</source>
        <translation>stav „%1“ nemá žádné řídicí body</translation>
    </message>
    <message>
        <source>state &apos;%1&apos;: control points must be 2D or 3D, got %2 coordinates</source>
        <translation>stav „%1“: řídicí body musí být 2D nebo 3D, zadaný počet souřadnic je %2</translation>
    </message>
    <message>
        <source>control points of state &apos;%1&apos;</source>
        <translation>řídicí body stavu „%1“</translation>
    </message>
    <message>
        <source>at most 255 arcs are supported (addresses are bytes), got %1</source>
        <translation>podporováno je nejvýše 255 hran (adresy jsou bajty), zadáno %1</translation>
    </message>
    <message>
        <source>arc &apos;%1&apos; connects states %2 -&gt; %3, but the automaton has %4 states</source>
        <translation>hrana „%1“ spojuje stavy %2 -&gt; %3, ale automat má počet stavů %4</translation>
    </message>
    <message>
        <source>%1 has a %2 x %3 matrix; it must be %4 x %5 (row convention: rows = dimension of &apos;%6&apos;, columns = dimension of &apos;%7&apos;)</source>
        <translation>%1 má matici %2 x %3; musí být %4 x %5 (řádková konvence: řádky = dimenze „%6“, sloupce = dimenze „%7“)</translation>
    </message>
    <message>
        <source>row %1 of %2 sums to %3, not 1: the map does not keep barycentric coordinates summing to 1</source>
        <translation>součet řádku %1 matice %2 je %3, nikoli 1: zobrazení nezachovává součet barycentrických souřadnic rovný 1</translation>
    </message>
    <message>
        <source>the weight of %1 must be a finite number &gt; 0, got %2</source>
        <translation>%1: váha musí být konečné číslo &gt; 0, zadáno %2</translation>
    </message>
    <message>
        <source>state &apos;%1&apos; has no outgoing arc: its attractor would be empty</source>
        <translation>stav „%1“ nemá žádnou výstupní hranu: jeho atraktor by byl prázdný</translation>
    </message>
    <message>
        <source>the barycentric part needs a non-empty square matrix</source>
        <translation>barycentrická část vyžaduje neprázdnou čtvercovou matici</translation>
    </message>
    <message>
        <source>cycle %1 has spectral radius %2 &gt;= 1 on the barycentric directions: repeating it does not contract, so the automaton has no attractor</source>
        <translation>cyklus %1 má v barycentrických směrech spektrální poloměr %2 &gt;= 1: jeho opakování není kontrakce, takže automat nemá atraktor</translation>
    </message>
    <message>
        <source>a fixed point needs a non-empty square matrix</source>
        <translation>pevný bod vyžaduje neprázdnou čtvercovou matici</translation>
    </message>
    <message>
        <source>the fixed point is not unique: 1 is a repeated eigenvalue</source>
        <translation>pevný bod není jednoznačný: 1 je násobné vlastní číslo</translation>
    </message>
    <message>
        <source>state %1 does not exist: the automaton has %2 states</source>
        <translation>stav %1 neexistuje: automat má počet stavů %2</translation>
    </message>
    <message>
        <source>one start set per state is needed: the automaton has %1 states, got %2 start sets</source>
        <translation>pro každý stav je potřeba jedna počáteční množina: automat má počet stavů %1, zadaný počet počátečních množin je %2</translation>
    </message>
    <message>
        <source>start set of state &apos;%1&apos;</source>
        <translation>počáteční množina stavu „%1“</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 je prázdná</translation>
    </message>
    <message>
        <source>%1 has %2 coordinates, the state&apos;s space has %3</source>
        <translation>%1 má počet souřadnic %2, prostor stavu má %3</translation>
    </message>
    <message>
        <source>at most 4e9 random-iteration samples, got %1</source>
        <translation>nejvýše 4e9 vzorků náhodné iterace, zadáno %1</translation>
    </message>
    <message>
        <source>the affine map&apos;s translation does not match its linear part</source>
        <translation>posunutí afinního zobrazení neodpovídá jeho lineární části</translation>
    </message>
    <message>
        <source>a barycentric frame in %1D needs %2 points, got a %3 x %4 matrix</source>
        <translation>barycentrický rámec v %1D vyžaduje %2 body, zadána matice %3 x %4</translation>
    </message>
    <message>
        <source>domain frame</source>
        <translation>rámec definičního oboru</translation>
    </message>
    <message>
        <source>image frame</source>
        <translation>rámec obrazu</translation>
    </message>
    <message>
        <source>affine map</source>
        <translation>afinní zobrazení</translation>
    </message>
    <message>
        <source>the image frame&apos;s points are affinely dependent (collinear in 2D)</source>
        <translation>body rámce obrazu jsou afinně závislé (ve 2D leží na jedné přímce)</translation>
    </message>
    <message>
        <source>map %1 does not act on the same space as map 1</source>
        <translation>zobrazení %1 nepůsobí na stejném prostoru jako zobrazení 1</translation>
    </message>
    <message>
        <source>map %1 (linear part)</source>
        <translation>zobrazení %1 (lineární část)</translation>
    </message>
    <message>
        <source>map %1 (translation)</source>
        <translation>zobrazení %1 (posunutí)</translation>
    </message>
    <message>
        <source>view %1 does not fit the IFS space</source>
        <translation>pohled %1 neodpovídá prostoru IFS</translation>
    </message>
    <message>
        <source>the IFS has %1 maps but %2 probabilities</source>
        <translation>IFS má %1 zobrazení, ale počet pravděpodobností je %2</translation>
    </message>
    <message>
        <source>probability of map %1 must be a finite number &gt;= 0</source>
        <translation>pravděpodobnost zobrazení %1 musí být konečné číslo &gt;= 0</translation>
    </message>
    <message>
        <source>the map probabilities sum to 0</source>
        <translation>součet pravděpodobností zobrazení je 0</translation>
    </message>
    <message>
        <source>the lifting needs %1 distinct free rows of the control points</source>
        <translation>zdvižení vyžaduje počet různých volných řádků řídicích bodů %1</translation>
    </message>
    <message>
        <source> and </source>
        <translation> a </translation>
    </message>
    <message>
        <source>the lifted matrix P is nearly singular (reciprocal condition number %1): M_i = P^-1 S_i P lose about %2 of 16 significant digits; control points %3 are almost collinear</source>
        <translation>zdvižená matice P je téměř singulární (převrácené číslo podmíněnosti %1): M_i = P^-1 S_i P ztrácí asi %2 z 16 platných číslic; řídicí body %3 leží téměř na jedné přímce</translation>
    </message>
    <message>
        <source>the lifted matrix P is nearly singular (reciprocal condition number %1): M_i = P^-1 S_i P lose about %2 of 16 significant digits; control points %3 are almost coplanar</source>
        <translation>zdvižená matice P je téměř singulární (převrácené číslo podmíněnosti %1): M_i = P^-1 S_i P ztrácí asi %2 z 16 platných číslic; řídicí body %3 leží téměř v jedné rovině</translation>
    </message>
    <message>
        <source>control points %1 are collinear, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>řídicí body %1 leží na jedné přímce, takže zdvižená matice P z 000 §2 je singulární a M_i = P^-1 S_i P není definováno; atraktor se počítá v barycentrickém tvaru</translation>
    </message>
    <message>
        <source>control points %1 are coplanar, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>řídicí body %1 leží v jedné rovině, takže zdvižená matice P z 000 §2 je singulární a M_i = P^-1 S_i P není definováno; atraktor se počítá v barycentrickém tvaru</translation>
    </message>
    <message>
        <source>control points %1 are affinely dependent, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>řídicí body %1 jsou afinně závislé, takže zdvižená matice P z 000 §2 je singulární a M_i = P^-1 S_i P není definováno; atraktor se počítá v barycentrickém tvaru</translation>
    </message>
    <message>
        <source>matrix S_%1 does not match %2 control points</source>
        <translation>matice S_%1 neodpovídá počtu řídicích bodů %2</translation>
    </message>
    <message>
        <source>matrix S_%1</source>
        <translation>matice S_%1</translation>
    </message>
    <message>
        <source>start points must have %1 (plane) or %2 (barycentric) coordinates</source>
        <translation>počet souřadnic počátečních bodů musí být %1 (v rovině) nebo %2 (barycentrické)</translation>
    </message>
    <message>
        <source>start points must have %1 (plane) or %2 (lifted) coordinates</source>
        <translation>počet souřadnic počátečních bodů musí být %1 (v rovině) nebo %2 (zdvižené)</translation>
    </message>
    <message>
        <source>a union needs at least one component</source>
        <translation>sjednocení vyžaduje alespoň jednu komponentu</translation>
    </message>
    <message>
        <source>component %1 has %2 maps, component 1 has %3: a block union needs equally many</source>
        <translation>komponenta %1 má %2 zobrazení, komponenta 1 má %3: blokové sjednocení vyžaduje stejný počet</translation>
    </message>
    <message>
        <source>probabilities must be finite and non-negative</source>
        <translation>pravděpodobnosti musí být konečné a nezáporné</translation>
    </message>
    <message>
        <source>the probabilities sum to zero</source>
        <translation>součet pravděpodobností je nula</translation>
    </message>
    <message>
        <source>the lattice lists %1 coordinates for %2 control points</source>
        <translation>počet mřížových souřadnic (%1) neodpovídá počtu řídicích bodů (%2)</translation>
    </message>
    <message>
        <source>a map is listed twice among the maps used</source>
        <translation>zobrazení je mezi použitými zobrazeními uvedeno dvakrát</translation>
    </message>
    <message>
        <source>map index %1 is out of range: the %2 layout has maps 0 to %3</source>
        <translation>index zobrazení %1 je mimo rozsah: rozložení %2 má zobrazení 0 až %3</translation>
    </message>
    <message>
        <source>at most %1 maps are supported, got %2</source>
        <translation>podporováno je nejvýše %1 zobrazení, zadáno %2</translation>
    </message>
    <message>
        <source>the barycentric part needs a non-empty matrix</source>
        <translation>barycentrická část vyžaduje neprázdnou matici</translation>
    </message>
</context>
<context>
    <name>awb::mesh</name>
    <message>
        <source>the mesh has no vertices</source>
        <translation>síť nemá žádné vrcholy</translation>
    </message>
    <message>
        <source>the mesh has no faces</source>
        <translation>síť nemá žádné stěny</translation>
    </message>
    <message>
        <source>face %1 has %2 vertices; a face needs at least 3</source>
        <translation>stěna %1 má %2 vrcholy; stěna potřebuje alespoň 3</translation>
    </message>
    <message>
        <source>face %1 refers to vertex %2, but the mesh has %3 vertices (0 to %4)</source>
        <translation>stěna %1 odkazuje na vrchol %2, ale síť má %3 vrcholů (0 až %4)</translation>
    </message>
    <message>
        <source>face %1 lists vertex %2 twice</source>
        <translation>stěna %1 uvádí vrchol %2 dvakrát</translation>
    </message>
    <message>
        <source>edge (%1, %2) is non-manifold: faces %3 meet there</source>
        <translation>hrana (%1, %2) není varietní: stýkají se v ní stěny %3</translation>
    </message>
    <message>
        <source>faces %1 and %2 are oriented inconsistently: both run from vertex %3 to vertex %4 (turn one of them over)</source>
        <translation>stěny %1 a %2 jsou orientovány nesouhlasně: obě vedou z vrcholu %3 do vrcholu %4 (jednu z nich obraťte)</translation>
    </message>
    <message>
        <source>vertex %1 is non-manifold: its %2 faces do not form one fan around it</source>
        <translation>vrchol %1 není varietní: jeho %2 stěn kolem něj netvoří jeden vějíř</translation>
    </message>
    <message>
        <source>mesh vertices need 3 coordinates, got %1</source>
        <translation>vrcholy sítě potřebují 3 souřadnice, mají %1</translation>
    </message>
    <message>
        <source>vertex %1 has a coordinate that is not a finite number</source>
        <translation>vrchol %1 má souřadnici, která není konečné číslo</translation>
    </message>
    <message>
        <source>face %1 has %2 vertices; Loop subdivision takes triangles only</source>
        <translation>stěna %1 má %2 vrcholů; Loopovo dělení přijímá jen trojúhelníky</translation>
    </message>
    <message>
        <source>a vertex&apos;s valence must be 3 to 64, got %1</source>
        <translation>valence vrcholu musí být 3 až 64, je %1</translation>
    </message>
    <message>
        <source>a characteristic map needs ring x 2 points</source>
        <translation>charakteristické zobrazení potřebuje body prstence × 2</translation>
    </message>
    <message>
        <source>a grid needs 1 to 1000 quads a side, got %1 x %2</source>
        <translation>mřížka potřebuje 1 až 1000 čtyřúhelníků na stranu, zadáno %1 x %2</translation>
    </message>
    <message>
        <source>there is no example mesh &apos;%1&apos;</source>
        <translation>síť „%1“ mezi příklady neexistuje</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1, řádek %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: &apos;%2&apos; není číslo</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a finite number</source>
        <translation>%1: „%2“ není konečné číslo</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a whole number</source>
        <translation>%1: „%2“ není celé číslo</translation>
    </message>
    <message>
        <source>%1: a vertex needs 3 coordinates, this one has %2</source>
        <translation>%1: vrchol potřebuje 3 souřadnice, tento jich má %2</translation>
    </message>
    <message>
        <source>%1: a face needs at least 3 vertices, this one has %2</source>
        <translation>%1: stěna potřebuje alespoň 3 vrcholy, tato jich má %2</translation>
    </message>
    <message>
        <source>%1: vertex index %2 is out of range (the file has %3 vertices)</source>
        <translation>%1: index vrcholu %2 je mimo rozsah (soubor má %3 vrcholů)</translation>
    </message>
    <message>
        <source>%1 holds no vertices</source>
        <translation>%1 neobsahuje žádné vrcholy</translation>
    </message>
    <message>
        <source>%1 holds no faces: not a polygon mesh</source>
        <translation>%1 neobsahuje žádné stěny: není to polygonová síť</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a face corner (v, v/vt, v//vn or v/vt/vn, nonzero whole numbers)</source>
        <translation>%1: „%2“ není roh stěny (v, v/vt, v//vn nebo v/vt/vn, nenulová celá čísla)</translation>
    </message>
    <message>
        <source>%1: relative vertex index %2 is out of range (%3 vertices precede it)</source>
        <translation>%1: relativní index vrcholu %2 je mimo rozsah (předchází mu %3 vrcholů)</translation>
    </message>
    <message>
        <source>%1 is not a valid OBJ file (tinyobjloader: %2)</source>
        <translation>%1 není platný soubor OBJ (tinyobjloader: %2)</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>soubor %1 je prázdný</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a header this reader takes: ASCII OFF of 3D points ([ST][C][N]OFF)</source>
        <translation>%1: „%2“ není hlavička, kterou tento čtecí modul přijímá: ASCII OFF s body ve 3D ([ST][C][N]OFF)</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not the counts line (vertices, faces and edges) of an OFF file</source>
        <translation>%1: „%2“ není řádek s počty (vrcholů, stěn a hran) souboru OFF</translation>
    </message>
    <message>
        <source>%1: %2 vertices and %3 faces need more lines than the %4 left in the file</source>
        <translation>%1: %2 vrcholů a %3 stěn potřebuje více řádků, než kolik jich v souboru zbývá (%4)</translation>
    </message>
    <message>
        <source>%1 ends after %2 of its %3 vertices</source>
        <translation>%1 končí po %2 z %3 vrcholů</translation>
    </message>
    <message>
        <source>%1 ends after %2 of its %3 faces</source>
        <translation>%1 končí po %2 z %3 stěn</translation>
    </message>
    <message>
        <source>%1: the face announces %2 vertices but lists %3</source>
        <translation>%1: stěna ohlašuje %2 vrcholů, ale uvádí %3</translation>
    </message>
    <message>
        <source>%1: data after the last face (the counts announce %2 vertices and %3 faces)</source>
        <translation>%1: data za poslední stěnou (počty ohlašují %2 vrcholů a %3 stěn)</translation>
    </message>
    <message>
        <source>%1: a property outside any element</source>
        <translation>%1: vlastnost mimo jakýkoli element</translation>
    </message>
    <message>
        <source>%1: unknown PLY property type &apos;%2&apos;</source>
        <translation>%1: neznámý typ vlastnosti PLY „%2“</translation>
    </message>
    <message>
        <source>%1: a list&apos;s length needs a whole-number type</source>
        <translation>%1: délka seznamu vyžaduje celočíselný typ</translation>
    </message>
    <message>
        <source>%1: property %2 appears twice in element %3</source>
        <translation>%1: vlastnost %2 se v elementu %3 vyskytuje dvakrát</translation>
    </message>
    <message>
        <source>%1 is not a PLY file (its first line is not &apos;ply&apos;)</source>
        <translation>%1 není soubor PLY (jeho první řádek není „ply“)</translation>
    </message>
    <message>
        <source>%1: the PLY header has no end_header line</source>
        <translation>%1: hlavička PLY nemá řádek end_header</translation>
    </message>
    <message>
        <source>%1: unsupported PLY format &apos;%2&apos; (ascii, binary_little_endian or binary_big_endian 1.0)</source>
        <translation>%1: nepodporovaný formát PLY „%2“ (ascii, binary_little_endian nebo binary_big_endian 1.0)</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a valid count</source>
        <translation>%1: „%2“ není platný počet</translation>
    </message>
    <message>
        <source>%1: element %2 appears twice</source>
        <translation>%1: element %2 se vyskytuje dvakrát</translation>
    </message>
    <message>
        <source>%1: unknown PLY header line &apos;%2&apos;</source>
        <translation type="vanished">%1: neznámý řádek hlavičky PLY „%2“</translation>
    </message>
    <message>
        <source>%1: the PLY header has no format line</source>
        <translation>%1: hlavička PLY nemá řádek format</translation>
    </message>
    <message>
        <source>%1: the vertex element needs the scalar properties x, y and z</source>
        <translation>%1: element vertex potřebuje skalární vlastnosti x, y a z</translation>
    </message>
    <message>
        <source>%1: the face element needs one list property vertex_indices (or vertex_index) of whole numbers</source>
        <translation>%1: element face potřebuje jednu seznamovou vlastnost vertex_indices (nebo vertex_index) s celými čísly</translation>
    </message>
    <message>
        <source>%1, line %2 (%3 %4)</source>
        <translation>%1, řádek %2 (%3 %4)</translation>
    </message>
    <message>
        <source>%1, %2 %3 (byte %4)</source>
        <translation>%1, %2 %3 (bajt %4)</translation>
    </message>
    <message>
        <source>%1: element %2 claims %3 items, more than the rest of the file can hold</source>
        <translation>%1: element %2 uvádí %3 záznamů, víc, než se vejde do zbytku souboru</translation>
    </message>
    <message>
        <source>%1: the data ends early (truncated)</source>
        <translation>%1: data končí předčasně (soubor je zkrácený)</translation>
    </message>
    <message>
        <source>%1: data after the last element (the header&apos;s counts do not match the data)</source>
        <translation>%1: data za posledním elementem (počty v hlavičce neodpovídají datům)</translation>
    </message>
    <message>
        <source>%1, byte %2</source>
        <translation>%1, bajt %2</translation>
    </message>
    <message>
        <source>%1: list length %2 is negative</source>
        <translation>%1: délka seznamu %2 je záporná</translation>
    </message>
    <message>
        <source>%1 has no file extension (expected .obj, .off or .ply)</source>
        <translation>%1 nemá příponu souboru (očekávána .obj, .off nebo .ply)</translation>
    </message>
    <message>
        <source>unknown mesh file extension &apos;%1&apos; of %2 (expected .obj, .off or .ply)</source>
        <translation>neznámá přípona souboru sítě „%1“ u %2 (očekávána .obj, .off nebo .ply)</translation>
    </message>
    <message>
        <source>cannot open %1</source>
        <translation>%1 nelze otevřít</translation>
    </message>
    <message>
        <source>cannot read %1</source>
        <translation>%1 nelze přečíst</translation>
    </message>
    <message>
        <source>%1: a NUL byte: not a text file</source>
        <translation>%1: bajt NUL: není to textový soubor</translation>
    </message>
    <message>
        <source>the mesh has %1 vertices, but %2 positions were given</source>
        <translation>síť má %1 vrcholů, ale bylo zadáno %2 poloh</translation>
    </message>
    <message>
        <source>mesh vertices</source>
        <translation>vrcholy sítě</translation>
    </message>
    <message>
        <source>depth %1 makes about %2 points; at most 2^31 are drawn</source>
        <translation>hloubka %1 dává asi %2 bodů; vykresluje se nejvýše 2^31</translation>
    </message>
    <message>
        <source>the mesh has more than %1 kinds of neighbourhood</source>
        <translation>síť má více než %1 druhů okolí</translation>
    </message>
    <message>
        <source>the irregular vertices do not separate</source>
        <translation>nepravidelné vrcholy se neoddělí</translation>
    </message>
    <message>
        <source>vertex %1 has %2 edges; valences above %3 are not supported</source>
        <translation>vrchol %1 má %2 hran; valence nad %3 nejsou podporovány</translation>
    </message>
    <message>
        <source>face %1 has %2 sides; faces of more than %3 sides are not supported</source>
        <translation>stěna %1 má %2 stran; stěny s více než %3 stranami nejsou podporovány</translation>
    </message>
    <message>
        <source>%1, line %2: the OpenSubdiv tag &apos;t %3&apos; is not applied: this version subdivides without creases, corners, holes or boundary rules, so the surface differs from OpenSubdiv&apos;s where it acts</source>
        <translation type="vanished">%1, řádek %2: značka OpenSubdiv &apos;t %3&apos; se neuplatní: tato verze dělí síť bez ostrých hran, rohů, děr a okrajových pravidel, takže se plocha tam, kde značka působí, liší od plochy OpenSubdiv</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 OpenSubdiv tags &apos;t %5&apos; are not applied: this version subdivides without creases, corners, holes or boundary rules, so the surface differs from OpenSubdiv&apos;s where they act</source>
        <translation type="vanished">%1, řádky %2 až %3: značky OpenSubdiv &apos;t %5&apos; (%4) se neuplatní: tato verze dělí síť bez ostrých hran, rohů, děr a okrajových pravidel, takže se plocha tam, kde působí, liší od plochy OpenSubdiv</translation>
    </message>
    <message>
        <source>%1: UTF-16 text of an odd number of bytes</source>
        <translation>%1: text v UTF-16 o lichém počtu bajtů</translation>
    </message>
    <message>
        <source>%1: invalid UTF-16 text (a lone surrogate)</source>
        <translation>%1: neplatný text v UTF-16 (osamocená náhradní hodnota)</translation>
    </message>
    <message>
        <source>%1: malformed PLY header line &apos;%2&apos;</source>
        <translation>%1: chybný řádek hlavičky PLY &apos;%2&apos;</translation>
    </message>
    <message>
        <source>%1: header line &apos;%2&apos; is not PLY 1.0&apos;s: skipped</source>
        <translation>%1: řádek hlavičky &apos;%2&apos; nepatří do PLY 1.0: přeskočen</translation>
    </message>
    <message>
        <source>%1 problems, the first %2: %3</source>
        <translation>%1 problémů, prvních %2: %3</translation>
    </message>
    <message>
        <source>%1 problems: %2</source>
        <translation>%1 problémů: %2</translation>
    </message>
    <message>
        <source>the ring analysis takes interior valences 3 to 64; this vertex has %1</source>
        <translation>analýza okolí bere vnitřní valence 3 až 64; tento vrchol má %1</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 more OpenSubdiv tag lines of other names are not applied either</source>
        <translation>%1, řádky %2 až %3: dalších %4 řádků značek OpenSubdiv jiných jmen se také neuplatní</translation>
    </message>
    <message>
        <source>%1: %2 header lines that are not PLY 1.0&apos;s, the first &apos;%3&apos;, are skipped</source>
        <translation>%1: %2 řádků hlavičky, které nepatří do PLY 1.0 (první &apos;%3&apos;), je přeskočeno</translation>
    </message>
    <message>
        <source>the crease on vertices %1 and %2 has sharpness %3; a sharpness is a number of 0 or more</source>
        <translation>ostrá hrana na vrcholech %1 a %2 má ostrost %3; ostrost je číslo 0 nebo větší</translation>
    </message>
    <message>
        <source>a crease names vertices %1 and %2, but no edge joins them</source>
        <translation>ostrá hrana uvádí vrcholy %1 a %2, ale žádná hrana je nespojuje</translation>
    </message>
    <message>
        <source>a corner names vertex %1, but the mesh has %2 vertices (0 to %3)</source>
        <translation>roh uvádí vrchol %1, ale počet vrcholů sítě je %2 (0 až %3)</translation>
    </message>
    <message>
        <source>the corner at vertex %1 has sharpness %2; a sharpness is a number of 0 or more</source>
        <translation>roh ve vrcholu %1 má ostrost %2; ostrost je číslo 0 nebo větší</translation>
    </message>
    <message>
        <source>a hole names face %1, but the mesh has %2 faces (0 to %3)</source>
        <translation>díra uvádí stěnu %1, ale počet stěn sítě je %2 (0 až %3)</translation>
    </message>
    <message>
        <source>%1, line %2: the OpenSubdiv tag &apos;t %3&apos; is not applied (this version applies crease, corner, hole, interpolateboundary, creasemethod and smoothtriangles), so the surface differs from OpenSubdiv&apos;s where it acts</source>
        <translation>%1, řádek %2: značka OpenSubdiv &apos;t %3&apos; se neuplatní (tato verze uplatňuje crease, corner, hole, interpolateboundary, creasemethod a smoothtriangles), takže se plocha tam, kde značka působí, liší od plochy z OpenSubdiv</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 OpenSubdiv tags &apos;t %5&apos; are not applied (this version applies crease, corner, hole, interpolateboundary, creasemethod and smoothtriangles), so the surface differs from OpenSubdiv&apos;s where they act</source>
        <translation>%1, řádky %2 až %3: značky OpenSubdiv &apos;t %5&apos; (celkem %4) se neuplatní (tato verze uplatňuje crease, corner, hole, interpolateboundary, creasemethod a smoothtriangles), takže se plocha tam, kde tyto značky působí, liší od plochy z OpenSubdiv</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; needs its counts as ints/floats/strings (like 2/1/0), got &apos;%3&apos;</source>
        <translation>%1: značka &apos;t %2&apos; vyžaduje počty ve tvaru ints/floats/strings (např. 2/1/0), zadáno „%3“</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; announces %3 values but has %4</source>
        <translation>%1: značka &apos;t %2&apos; ohlašuje počet hodnot %3, ale obsahuje jich %4</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; needs %3</source>
        <translation>%1: značka &apos;t %2&apos; vyžaduje %3</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; names vertex %3, but the file has %4 vertices (tags count from 0: 0 to %5)</source>
        <translation>%1: značka &apos;t %2&apos; uvádí vrchol %3, ale počet vrcholů v souboru je %4 (značky číslují od 0: 0 až %5)</translation>
    </message>
    <message>
        <source>%1: the hole names face %2, but the file has %3 faces (0 to %4)</source>
        <translation>%1: díra uvádí stěnu %2, ale počet stěn v souboru je %3 (0 až %4)</translation>
    </message>
    <message>
        <source>Chaikin&apos;s creases last %1 more levels here; the mesh would have more than %2 faces (use the uniform crease method)</source>
        <translation>počet úrovní, po které zde Chaikinovy ostré hrany ještě přetrvají: %1; síť by měla více než %2 stěn (použijte rovnoměrnou metodu ostrých hran)</translation>
    </message>
    <message>
        <source>the semi-sharp features last %1 levels; the mesh would have more than %2 faces before its limit positions can be taken</source>
        <translation>počet úrovní, po které přetrvají poloostré prvky: %1; než by bylo možné určit limitní polohy, měla by síť více než %2 stěn</translation>
    </message>
    <message>
        <source>pairs of vertices and one sharpness, or one per pair</source>
        <translation>dvojice vrcholů a jednu ostrost, nebo jednu ostrost pro každou dvojici</translation>
    </message>
    <message>
        <source>vertices and one sharpness, or one per vertex</source>
        <translation>vrcholy a jednu ostrost, nebo jednu ostrost pro každý vrchol</translation>
    </message>
    <message>
        <source>the faces it makes holes</source>
        <translation>stěny, z nichž udělá díry</translation>
    </message>
    <message>
        <source>one whole number: 0 none, 1 edge and corner, 2 edge only</source>
        <translation>jedno celé číslo: 0 žádná, 1 hrany a rohy, 2 jen hrany</translation>
    </message>
    <message>
        <source>one word: normal or chaikin</source>
        <translation>jedno slovo: normal nebo chaikin</translation>
    </message>
    <message>
        <source>one word: catmark or smooth</source>
        <translation>jedno slovo: catmark nebo smooth</translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation> a %1 dalších</translation>
    </message>
    <message>
        <source>%1 faces named a vertex twice in a row and now name it once (faces %2)</source>
        <translation>%1 stěn uvádělo vrchol dvakrát za sebou a nyní ho uvádí jednou (stěny %2)</translation>
    </message>
    <message>
        <source>%1 faces were left with fewer than three vertices and were removed (faces %2; the later faces move up)</source>
        <translation>%1 stěn mělo méně než tři vrcholy a bylo odstraněno (stěny %2; další stěny se posouvají)</translation>
    </message>
    <message>
        <source>%1 boundary vertices at the position of another were welded into it (vertices %2; they stay, used by no face)</source>
        <translation>%1 hraničních vrcholů v poloze jiného vrcholu bylo do něj svařeno (vrcholy %2; zůstávají, nepoužívá je žádná stěna)</translation>
    </message>
    <message>
        <source>%1 faces were turned over to the orientation of the surface they belong to (faces %2)</source>
        <translation>%1 stěn bylo otočeno podle orientace plochy, k níž patří (stěny %2)</translation>
    </message>
    <message>
        <source>the surface of face %1 cannot be oriented (it is a Möbius band or contains one): left as it is</source>
        <translation>plochu stěny %1 nelze orientovat (je to Möbiova páska nebo ji obsahuje): ponechána beze změny</translation>
    </message>
    <message>
        <source>%1 vertices whose faces formed several fans were split, one vertex per fan (vertices %2; the %3 new vertices are numbered from %4)</source>
        <translation>%1 vrcholů, jejichž stěny tvořily několik vějířů, bylo rozděleno, jeden vrchol na vějíř (vrcholy %2; %3 nových vrcholů má čísla od %4)</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <translation>(%1, %2)</translation>
    </message>
    <message>
        <source>%1 edges join three or more faces (%2): no choice of sheets is canonical, so they are not repaired</source>
        <translation type="vanished">%1 hran spojuje tři nebo více stěn (%2): žádná volba listů není kanonická, proto nejsou opraveny</translation>
    </message>
    <message>
        <source>%1 edges join three or more faces (%2): no choice of sheets is canonical, so they are not repaired; they are drawn as OpenSubdiv draws them, as infinitely sharp creases</source>
        <translation>%1 hran spojuje tři nebo více stěn (%2): žádná volba listů není kanonická, proto se neopravují; kreslí se tak, jak je kreslí OpenSubdiv, jako nekonečně ostré hrany</translation>
    </message>
    <message>
        <source>%1(%2, %3)</source>
        <translation>%1(%2, %3)</translation>
    </message>
    <message>
        <source>the vertices as corners</source>
        <translation>vrcholy jako rohy</translation>
    </message>
    <message>
        <source>%1 of the vertices as corners, the others on the creases</source>
        <translation>%1 vrcholů jako rohy, ostatní na ostrých hranách</translation>
    </message>
    <message>
        <source>non-manifold: %1 vertices (%2), drawn as OpenSubdiv draws them: %3</source>
        <translation>nevarietní: %1 vrcholů (%2), kreslené tak, jak je kreslí OpenSubdiv: %3</translation>
    </message>
    <message>
        <source>non-manifold: %1 edges (%2) and %3 vertices (%4), drawn as OpenSubdiv draws them: the edges as infinitely sharp creases, %5</source>
        <translation>nevarietní: %1 hran (%2) a %3 vrcholů (%4), kreslené tak, jak je kreslí OpenSubdiv: hrany jako nekonečně ostré hrany, %5</translation>
    </message>
    <message>
        <source>its largest eigenvalues below 1 are not real and positive</source>
        <translation>jeho největší vlastní čísla menší než 1 nejsou reálná a kladná</translation>
    </message>
    <message>
        <source>%1 is a defective eigenvalue (a Jordan block) among the two largest: Reif&apos;s criterion takes them diagonalizable (not decided)</source>
        <translation type="vanished">%1 je defektní vlastní číslo (Jordanův blok) mezi dvěma největšími: Reifovo kritérium předpokládá diagonalizovatelnost (nerozhodnuto)</translation>
    </message>
    <message>
        <source>lambda2 = lambda3 = %1: the tangent plane is not determined by the two largest</source>
        <translation>lambda2 = lambda3 = %1: tečná rovina není určena dvěma největšími</translation>
    </message>
    <message>
        <source>its characteristic map is not regular</source>
        <translation>jeho charakteristické zobrazení není regulární</translation>
    </message>
    <message>
        <source>its characteristic map is not injective</source>
        <translation>jeho charakteristické zobrazení není prosté</translation>
    </message>
    <message>
        <source>%1: %2 crease tags name an edge tagged before (the first: %3 %4): each edge keeps its last sharpness, as OpenSubdiv applies them</source>
        <translation>%1: %2 značek ostré hrany jmenuje hranu označenou již dříve (první: %3 %4): každá hrana si ponechá poslední ostrost, jak je OpenSubdiv aplikuje</translation>
    </message>
    <message>
        <source>%1: %2 corner tags name a vertex tagged before (the first: %3): each vertex keeps its last sharpness, as OpenSubdiv applies them</source>
        <translation>%1: %2 značek rohu jmenuje vrchol označený již dříve (první: %3): každý vrchol si ponechá poslední ostrost, jak je OpenSubdiv aplikuje</translation>
    </message>
    <message>
        <source>%1: %2 hole tags name a face made a hole before</source>
        <translation>%1: %2 značek díry jmenuje stěnu, která již díra je</translation>
    </message>
    <message>
        <source>lambda1 = lambda2 = %1 is a Jordan block: the rings shear, and Reif&apos;s criterion holds for the map of its eigenvector and generalized eigenvector</source>
        <translation>lambda1 = lambda2 = %1 je Jordanův blok: prstence se zkosí a Reifovo kritérium platí pro zobrazení jeho vlastního a zobecněného vlastního vektoru</translation>
    </message>
    <message>
        <source>lambda1 = lambda2 = %1 has two eigenvectors and a Jordan chain: the normal and the rings follow the map of the two eigenvectors</source>
        <translation>lambda1 = lambda2 = %1 má dva vlastní vektory a Jordanův řetězec: normála i prstence se řídí zobrazením obou vlastních vektorů</translation>
    </message>
    <message>
        <source>lambda2 = %1 is a Jordan block: its chain&apos;s top term k lambda2^k dominates, and Reif&apos;s criterion holds for the map of the eigenvectors of lambda1 and of the chain&apos;s top</source>
        <translation>lambda2 = %1 je Jordanův blok: převládá člen k lambda2^k vrcholu jeho řetězce a Reifovo kritérium platí pro zobrazení vlastních vektorů lambda1 a vrcholu řetězce</translation>
    </message>
    <message>
        <source>%1 is a defective eigenvalue with a Jordan chain longer than two, or more than one chain: Reif&apos;s criterion is not decided there</source>
        <translation>%1 je defektní vlastní číslo s Jordanovým řetězcem delším než dva, nebo s více řetězci: Reifovo kritérium zde není rozhodnuto</translation>
    </message>
    <message>
        <source>the eigenvectors of lambda1 and lambda2 vanish on the crease of edge %1, whose own tangent (a smaller eigenvalue) leaves their tangent plane: not C1 for generic data</source>
        <translation>vlastní vektory lambda1 a lambda2 jsou nulové na ostré hraně %1, jejíž vlastní tečna (menší vlastní číslo) opouští jejich tečnou rovinu: pro obecná data není C1</translation>
    </message>
</context>
<context>
    <name>awb::render</name>
    <message>
        <source>raster size must be between 1x1 and 32768x32768, got %1x%2</source>
        <translation>velikost rastru musí být mezi 1x1 a 32768x32768, zadáno %1x%2</translation>
    </message>
    <message>
        <source>supersampling must be 1 to 4 cells per pixel side, got %1</source>
        <translation>nadvzorkování musí být 1 až 4 buňky na stranu pixelu, zadáno %1</translation>
    </message>
    <message>
        <source>the supersampled raster would hold more than 1.2e9 cells</source>
        <translation>nadvzorkovaný rastr by měl více než 1.2e9 buněk</translation>
    </message>
    <message>
        <source>raster world rectangle is empty or not finite</source>
        <translation>obdélník rastru ve světových souřadnicích je prázdný nebo není konečný</translation>
    </message>
    <message>
        <source>cannot merge density images of different sizes or modes</source>
        <translation>obrazy hustoty různých velikostí nebo režimů nelze sloučit</translation>
    </message>
    <message>
        <source>density image does not match its frame</source>
        <translation>obraz hustoty neodpovídá svému rámci</translation>
    </message>
    <message>
        <source>a view does not fit the IFS space</source>
        <translation>pohled neodpovídá prostoru IFS</translation>
    </message>
    <message>
        <source>there is no IFS to draw</source>
        <translation>není žádný IFS k vykreslení</translation>
    </message>
    <message>
        <source>the IFS has no view to draw it with</source>
        <translation>IFS nemá žádný pohled, pomocí něhož by jej bylo možné vykreslit</translation>
    </message>
    <message>
        <source>the colour table does not cover the address labels</source>
        <translation>tabulka barev nepokrývá popisky adres</translation>
    </message>
</context>
<context>
    <name>awb::schemes</name>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 není konečné číslo</translation>
    </message>
    <message>
        <source>%1 = %2 &lt; 1</source>
        <translation>%1 = %2 &lt; 1</translation>
    </message>
    <message>
        <source>%1 = %2: on the circle %1 = 1, so %3 is an isometry, not a contraction</source>
        <translation>%1 = %2: na kružnici %1 = 1, takže %3 je izometrie, nikoli kontrakce</translation>
    </message>
    <message>
        <source>%1 = %2 &gt; 1, so %3 expands</source>
        <translation>%1 = %2 &gt; 1, takže %3 expanduje</translation>
    </message>
    <message>
        <source>y must be a finite nonzero number (t = 1/2 + i y)</source>
        <translation>y musí být konečné nenulové číslo (t = 1/2 + i y)</translation>
    </message>
    <message>
        <source>t = 1/2 + i y with y = %1: %2</source>
        <translation>t = 1/2 + i y pro y = %1: %2</translation>
    </message>
    <message>
        <source>depth must be between 1 and 24, got %1</source>
        <translation>hloubka musí být mezi 1 a 24, zadáno %1</translation>
    </message>
    <message>
        <source>the subdivision parameter t</source>
        <translation>parametr subdivize t</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies inside both discs: the IFS is hyperbolic (contraction factor %4) and its attractor is a connected curve (Theorem 3.7.2)</source>
        <translation>t = %1: %2, %3. t leží uvnitř obou kruhů: IFS je hyperbolický (koeficient kontrakce %4) a jeho atraktor je souvislá křivka (Theorem 3.7.2)</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies outside both discs |t| &lt; 1 and |1 - t| &lt; 1: the IFS is not hyperbolic and has no attractor</source>
        <translation>t = %1: %2, %3. t leží vně obou kruhů |t| &lt; 1 a |1 - t| &lt; 1: IFS není hyperbolický a nemá atraktor</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies outside the disc %4: the IFS is not hyperbolic and has no attractor</source>
        <translation>t = %1: %2, %3. t leží vně kruhu %4: IFS není hyperbolický a nemá atraktor</translation>
    </message>
    <message>
        <source>a Bézier curve needs at least 2 control points (degree &gt;= 1), got %1</source>
        <translation>Bézierova křivka vyžaduje alespoň 2 řídicí body (stupeň &gt;= 1), zadáno %1</translation>
    </message>
    <message>
        <source>control points</source>
        <translation>řídicí body</translation>
    </message>
    <message>
        <source>all control points coincide: the curve is a single point and the lifted matrix of 000 §2 is singular</source>
        <translation>všechny řídicí body splývají: křivka je jediný bod a zdvižená matice podle 000 §2 je singulární</translation>
    </message>
    <message>
        <source>depth must be between 0 and 24, got %1</source>
        <translation>hloubka musí být mezi 0 a 24, zadáno %1</translation>
    </message>
    <message>
        <source>the Takagi function needs a finite x</source>
        <translation>Takagiho funkce vyžaduje konečné x</translation>
    </message>
    <message>
        <source>the number of Takagi terms must be &gt;= 0</source>
        <translation>počet členů Takagiho funkce musí být &gt;= 0</translation>
    </message>
    <message>
        <source>binary codes longer than 60 digits are not supported</source>
        <translation>binární kódy delší než 60 číslic nejsou podporovány</translation>
    </message>
    <message>
        <source>a binary code has digits 0 and 1 only (digit %1 is %2)</source>
        <translation>binární kód obsahuje pouze číslice 0 a 1 (číslice %1 je %2)</translation>
    </message>
    <message>
        <source>Takagi image: needs at least 2 control points, got %1</source>
        <translation>Takagiho obraz: jsou potřeba alespoň 2 řídicí body, zadáno %1</translation>
    </message>
    <message>
        <source>Takagi image: control points and y must be finite</source>
        <translation>Takagiho obraz: řídicí body a y musí být konečné</translation>
    </message>
    <message>
        <source>Takagi image: depth %1 is outside 1..20</source>
        <translation>Takagiho obraz: hloubka %1 je mimo rozsah 1..20</translation>
    </message>
    <message>
        <source>control points must have 2 or 3 coordinates, got %1</source>
        <translation>řídicí body musí mít 2 nebo 3 souřadnice, zadáno %1</translation>
    </message>
    <message>
        <source>%1 control points are too few: affine combinations in %2D need at least %3 that are not collinear</source>
        <translation>počet řídicích bodů %1 je příliš malý: afinní kombinace ve %2D vyžadují alespoň %3 body, které neleží na jedné přímce</translation>
    </message>
    <message>
        <source>%1 control points are too few: affine combinations in %2D need at least %3 that are not coplanar</source>
        <translation>počet řídicích bodů %1 je příliš malý: afinní kombinace ve %2D vyžadují alespoň %3 body, které neleží v jedné rovině</translation>
    </message>
    <message>
        <source>the control points are all collinear: they must span the plane to write every image point as their affine combination (000 eq. (5))</source>
        <translation>všechny řídicí body leží na jedné přímce: musí generovat rovinu, aby bylo možné každý obrazový bod zapsat jako jejich afinní kombinaci (000 eq. (5))</translation>
    </message>
    <message>
        <source>the control points are all coplanar: they must span space to write every image point as their affine combination (000 eq. (5))</source>
        <translation>všechny řídicí body leží v jedné rovině: musí generovat prostor, aby bylo možné každý obrazový bod zapsat jako jejich afinní kombinaci (000 eq. (5))</translation>
    </message>
    <message>
        <source>the point has %1 coordinates, the control points have %2</source>
        <translation>bod má počet souřadnic %1, řídicí body %2</translation>
    </message>
    <message>
        <source>point</source>
        <translation>bod</translation>
    </message>
    <message>
        <source>the IFS has no maps</source>
        <translation>IFS nemá žádná zobrazení</translation>
    </message>
    <message>
        <source>map f_%1 is not a map of %2D points like the control points</source>
        <translation>zobrazení f_%1 není zobrazením %2D bodů jako řídicí body</translation>
    </message>
    <message>
        <source>map f_%1 (linear part)</source>
        <translation>zobrazení f_%1 (lineární část)</translation>
    </message>
    <message>
        <source>map f_%1 (translation)</source>
        <translation>zobrazení f_%1 (posunutí)</translation>
    </message>
    <message>
        <source>Koch curve with control points</source>
        <translation>Kochova křivka s řídicími body</translation>
    </message>
    <message>
        <source>Sierpinski gasket with control points</source>
        <translation>Sierpinského trojúhelník s řídicími body</translation>
    </message>
    <message>
        <source>%1 needs %2 control points in the plane, got %3 with %4 coordinates</source>
        <translation>%1: počet řídicích bodů v rovině musí být %2, zadáno %3 (počet souřadnic: %4)</translation>
    </message>
    <message>
        <source>Bézier degree must be at least 1</source>
        <translation>stupeň Bézierovy křivky musí být alespoň 1</translation>
    </message>
    <message>
        <source>B-spline degree must be at least 1</source>
        <translation>stupeň B-spline musí být alespoň 1</translation>
    </message>
    <message>
        <source>a B-spline of degree %1 needs at least %2 control points (%3 knots), got %4 knots</source>
        <translation>B-spline stupně %1: počet řídicích bodů musí být alespoň %2 (počet uzlů %3), zadáno uzlů: %4</translation>
    </message>
    <message>
        <source>B-spline knot %1 is not a finite number</source>
        <translation>uzel B-spline %1 není konečné číslo</translation>
    </message>
    <message>
        <source>B-spline knots must be nondecreasing (knot %1)</source>
        <translation>uzly B-spline musí tvořit neklesající posloupnost (uzel %1)</translation>
    </message>
    <message>
        <source>B-spline knot vector has an empty domain</source>
        <translation>uzlový vektor B-spline má prázdný definiční obor</translation>
    </message>
    <message>
        <source>an end-interpolating B-spline of degree %1 needs at least %2 control points</source>
        <translation>B-spline stupně %1 interpolující koncové body: počet řídicích bodů musí být alespoň %2</translation>
    </message>
    <message>
        <source>B-spline needs %1 control points, got %2</source>
        <translation>B-spline: počet řídicích bodů musí být %1, zadáno %2</translation>
    </message>
    <message>
        <source>scheme %1: the dilation must be at least 2</source>
        <translation>schéma %1: dilatace musí být alespoň 2</translation>
    </message>
    <message>
        <source>scheme %1: the mask holds a non-finite weight</source>
        <translation>schéma %1: maska obsahuje nekonečnou váhu</translation>
    </message>
    <message>
        <source>scheme %1: the mask is empty</source>
        <translation>schéma %1: maska je prázdná</translation>
    </message>
    <message>
        <source>scheme %1: the mask entries of class (%2, %3) mod %4 sum to %5, not 1</source>
        <translation>schéma %1: součet prvků masky třídy (%2, %3) mod %4 je %5, nikoli 1</translation>
    </message>
    <message>
        <source>scheme %1: local subdivision matrix not closed</source>
        <translation>schéma %1: lokální subdivizní matice není uzavřená</translation>
    </message>
    <message>
        <source>scheme %1: the local subdivision matrix has no eigenvalue 1</source>
        <translation>schéma %1: lokální subdivizní matice nemá vlastní číslo 1</translation>
    </message>
    <message>
        <source>scheme %1: the limit eigenvector sums to 0</source>
        <translation>schéma %1: součet limitního vlastního vektoru je 0</translation>
    </message>
    <message>
        <source>box spline %1: its directions sum to an odd vector, so the mask has no lattice-point centre</source>
        <translation>box spline %1: součet jeho směrů je lichý vektor, takže maska nemá střed v mřížovém bodě</translation>
    </message>
    <message>
        <source>bicubic B-spline</source>
        <translation>bikubický B-spline</translation>
    </message>
    <message>
        <source>Loop (three-direction quartic box spline)</source>
        <translation>Loop (třísměrový box spline čtvrtého stupně)</translation>
    </message>
    <message>
        <source>Kobbelt √3 (two rounds)</source>
        <translation>Kobbelt √3 (dvě kola)</translation>
    </message>
    <message>
        <source>positive (edge rotated 90° counter-clockwise)</source>
        <translation>kladné (hrana otočená o 90° proti směru hodinových ručiček)</translation>
    </message>
    <message>
        <source>negative (edge rotated 90° clockwise)</source>
        <translation>záporné (hrana otočená o 90° po směru hodinových ručiček)</translation>
    </message>
    <message>
        <source>constant</source>
        <comment>β sign</comment>
        <translation>konstantní</translation>
    </message>
    <message>
        <source>Positive normal: the edge vector P_i P_{i+1} rotated 90° counter-clockwise; negative: rotated clockwise. d_i = |P_i P_{i+1}| n_i. In the β signs (-1)^i, (-1)^(k+i), (-1)^(k+1), k is the level of the polygon being subdivided (the first step has k = 0) and i the 0-based index of the edge.</source>
        <translation>Kladná normála: vektor hrany P_i P_{i+1} otočený o 90° proti směru hodinových ručiček; záporná: otočený po směru hodinových ručiček. d_i = |P_i P_{i+1}| n_i. Ve znaménkách β (-1)^i, (-1)^(k+i), (-1)^(k+1) je k úroveň dělené polygonu (první krok má k = 0) a i index hrany číslovaný od 0.</translation>
    </message>
    <message>
        <source>p = %1: the normal-vector scheme needs p &gt;= 2 rules, one (α_j, β_j) pair each</source>
        <translation>p = %1: schéma normálových vektorů vyžaduje p &gt;= 2 pravidel, každé s jednou dvojicí (α_j, β_j)</translation>
    </message>
    <message>
        <source>β has %1 values but α has %2: eq. (1) needs one (α_j, β_j) pair per rule j = 0..p-1</source>
        <translation>počet hodnot β (%1) se liší od počtu hodnot α (%2): eq. (1) vyžaduje jednu dvojici (α_j, β_j) pro každé pravidlo j = 0..p-1</translation>
    </message>
    <message>
        <source>α_%1 is not a finite number</source>
        <translation>α_%1 není konečné číslo</translation>
    </message>
    <message>
        <source>β_%1 is not a finite number</source>
        <translation>β_%1 není konečné číslo</translation>
    </message>
    <message>
        <source>%1 β signs given for p = %2 rules: give none, one for all rules, or one per rule</source>
        <translation>počet znamének β (%1) neodpovídá počtu pravidel p = %2: zadejte žádné, jedno pro všechna pravidla, nebo jedno pro každé pravidlo</translation>
    </message>
    <message>
        <source>p = %1, α = %2, β = %3, β signs (%4), normals %5</source>
        <translation>p = %1, α = %2, β = %3, znaménka β (%4), normály: %5</translation>
    </message>
    <message>
        <source>the normal-vector scheme works in the plane: control points need 2 coordinates, got %1</source>
        <translation>schéma normálových vektorů pracuje v rovině: řídicí body potřebují 2 souřadnice, zadáno %1</translation>
    </message>
    <message>
        <source>control polygon</source>
        <translation>řídicí polygon</translation>
    </message>
    <message>
        <source>a closed control polygon needs at least %1 points, got %2</source>
        <translation>uzavřený řídicí polygon: počet bodů musí být alespoň %1, zadáno %2</translation>
    </message>
    <message>
        <source>an open control polygon needs at least %1 points, got %2</source>
        <translation>otevřený řídicí polygon: počet bodů musí být alespoň %1, zadáno %2</translation>
    </message>
    <message>
        <source>open control polygons need α_0 = β_0 = 0: rule 0 at the last point (i = p^k n in eq. (1)) would use a point after the end; close the polygon instead</source>
        <translation>otevřené řídicí polygony vyžadují α_0 = β_0 = 0: pravidlo 0 v posledním bodě (i = p^k n v eq. (1)) by použilo bod za koncem; polygon raději uzavřete</translation>
    </message>
    <message>
        <source>the number of subdivision steps cannot be negative, got %1</source>
        <translation>počet kroků subdivize nemůže být záporný, zadáno %1</translation>
    </message>
    <message>
        <source>the subdivision level cannot be negative, got %1</source>
        <translation>úroveň subdivize nemůže být záporná, zadáno %1</translation>
    </message>
    <message>
        <source>%1 subdivision steps of a polygon with %2 edges would make %3 points (at most %4); use fewer steps</source>
        <translation>subdivize polygonu (počet hran: %2) v %1 krocích by dala %3 bodů (nejvýše %4); použijte méně kroků</translation>
    </message>
    <message>
        <source>convergent: every edge shrinks by a factor of at most %1 per step, so ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (longest initial edge) and F^k is a Cauchy sequence (the argument of 001 Theorem 1); non-rectifiable: the polygon length grows by a factor of at least %3 per step (001 Theorem 2)</source>
        <translation>konvergentní: každá hrana se v každém kroku zkrátí nejvýše koeficientem %1, takže ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (nejdelší počáteční hrana) a F^k je cauchyovská posloupnost (argument z 001 Theorem 1); nerektifikovatelná: délka polygonu roste v každém kroku alespoň koeficientem %3 (001 Theorem 2)</translation>
    </message>
    <message>
        <source>convergent: every edge shrinks by a factor of at most %1 per step, so ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (longest initial edge) and F^k is a Cauchy sequence (the argument of 001 Theorem 1)</source>
        <translation>konvergentní: každá hrana se v každém kroku zkrátí nejvýše koeficientem %1, takže ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (nejdelší počáteční hrana) a F^k je cauchyovská posloupnost (argument z 001 Theorem 1)</translation>
    </message>
    <message>
        <source>not decided: the one-step edge bound is %1 &gt;= 1, so the argument of 001 Theorem 1 does not apply (see the measured edge lengths per level)</source>
        <translation>nerozhodnuto: jednokrokový odhad hran je %1 &gt;= 1, takže argument z 001 Theorem 1 nelze použít (viz naměřené délky hran na jednotlivých úrovních)</translation>
    </message>
    <message>
        <source>α_0 and β_0 are not both 0: the new edge across each old vertex joins two old edges and is not the image of one edge, so no IFS of one similarity per new edge exists</source>
        <translation>α_0 a β_0 nejsou obě 0: nová hrana přes každý starý vrchol spojuje dvě staré hrany a není obrazem jedné hrany, takže IFS s jednou podobností pro každou novou hranu neexistuje</translation>
    </message>
    <message>
        <source>new edge %1 of the unit edge has length %2 &gt;= 1: no map would contract</source>
        <translation>nová hrana %1 jednotkové hrany má délku %2 &gt;= 1: žádné zobrazení by nebylo kontrakcí</translation>
    </message>
    <message>
        <source>no IFS of %1 similarities (each new edge taken forward or reversed, plain or mirrored: %2 patterns) reproduces the polygons of the first %3 steps; the β sign changes with the level, so the rules repeat only every two steps (an IFS would need p^2 maps)</source>
        <translation>žádný IFS z %1 podobností (každá nová hrana vzatá dopředu nebo obráceně, přímo nebo zrcadleně: %2 vzorů) nereprodukuje polygony prvních %3 kroků; znaménko β se mění s úrovní, takže pravidla se opakují jen každé dva kroky (IFS by potřeboval p^2 zobrazení)</translation>
    </message>
    <message>
        <source>no IFS of %1 similarities (each new edge taken forward or reversed, plain or mirrored: %2 patterns) reproduces the polygons of the first %3 steps</source>
        <translation>žádný IFS z %1 podobností (každá nová hrana vzatá dopředu nebo obráceně, přímo nebo zrcadleně: %2 vzorů) nereprodukuje polygony prvních %3 kroků</translation>
    </message>
    <message>
        <source>no equivalent IFS: %1</source>
        <translation>žádný ekvivalentní IFS: %1</translation>
    </message>
    <message>
        <source>edge %1 of the control polygon is subdivided with rules no similarity copy of the unit edge&apos;s limit reproduces</source>
        <translation>hrana %1 řídicího polygonu se dělí pravidly, která nereprodukuje žádná podobná kopie limity jednotkové hrany</translation>
    </message>
    <message>
        <source>Lévy C curve</source>
        <translation>Lévyho C křivka</translation>
    </message>
    <message>
        <source>binary interpolatory; new point at the apex of a right isosceles triangle</source>
        <translation>binární interpolační; nový bod ve vrcholu pravoúhlého rovnoramenného trojúhelníku</translation>
    </message>
    <message>
        <source>Dragon curve</source>
        <translation>Dračí křivka</translation>
    </message>
    <message>
        <source>scheme (2) with β_1 = (-1)^i / 2: the bump alternates sides along the curve</source>
        <translation>schéma (2) s β_1 = (-1)^i / 2: výstupek se podél křivky střídá na obě strany</translation>
    </message>
    <message>
        <source>Sierpiński gasket (arrowhead curve)</source>
        <translation>Sierpińského trojúhelník (šipková křivka)</translation>
    </message>
    <message>
        <source>non-stationary and non-uniform, as in the paper: β_1 = β_2 = (-1)^(k+i) √3/4 flips with the level k and the edge i; the polygons tend to the gasket</source>
        <translation>nestacionární a neuniformní, jako v článku: β_1 = β_2 = (-1)^(k+i) √3/4 mění znaménko s úrovní k a hranou i; polygony konvergují k trojúhelníku</translation>
    </message>
    <message>
        <source>Koch curve</source>
        <translation>Kochova křivka</translation>
    </message>
    <message>
        <source>quaternary interpolatory; the limit is the classic Koch curve</source>
        <translation>kvaternární interpolační; limitou je klasická Kochova křivka</translation>
    </message>
    <message>
        <source>Koch snowflake</source>
        <translation>Kochova vločka</translation>
    </message>
    <message>
        <source>the triangle traversed counter-clockwise with negative normals, so every bump points outwards (NOTES.md)</source>
        <translation>trojúhelník procházený proti směru hodinových ručiček se zápornými normálami, takže každý výstupek míří ven (NOTES.md)</translation>
    </message>
    <message>
        <source>Tigerhead-like curve</source>
        <translation>Křivka podobná tygří hlavě</translation>
    </message>
    <message>
        <source>α = (0, -1/4, 1/2, 5/4), β = (0, 1/3, 1/2, 1/3): rules 1 and 3 lie outside the edge, so the curve overlaps itself</source>
        <translation>α = (0, -1/4, 1/2, 5/4), β = (0, 1/3, 1/2, 1/3): pravidla 1 a 3 leží mimo hranu, takže křivka sama sebe překrývá</translation>
    </message>
    <message>
        <source>Human-like curve</source>
        <translation>Křivka podobná lidské postavě</translation>
    </message>
    <message>
        <source>β = (-1)^(k+1) (0, 1/3, 1/2, 1/3): the bumps point down at the first step (k = 0) and flip at every level</source>
        <translation>β = (-1)^(k+1) (0, 1/3, 1/2, 1/3): výstupky v prvním kroku (k = 0) míří dolů a na každé úrovni se překlopí</translation>
    </message>
    <message>
        <source>Approximating curve</source>
        <translation>Aproximační křivka</translation>
    </message>
    <message>
        <source>α_0 = -1/2 moves the old points, so the polygon must be closed; the text does not give the quadrilateral of Fig. 3(c): a unit square traversed counter-clockwise is assumed</source>
        <translation>α_0 = -1/2 posouvá staré body, takže polygon musí být uzavřený; text neuvádí čtyřúhelník z Fig. 3(c): předpokládá se jednotkový čtverec procházený proti směru hodinových ručiček</translation>
    </message>
    <message>
        <source>Crown-like curve</source>
        <translation>Křivka podobná koruně</translation>
    </message>
    <message>
        <source>6-ary interpolatory</source>
        <translation>6-ární interpolační</translation>
    </message>
    <message>
        <source>7-ary square-wave curve</source>
        <translation>7-ární křivka obdélníkové vlny</translation>
    </message>
    <message>
        <source>the paper calls it the Minkowski curve; it equals the Minkowski sausage only at level 1 (its middle edge has length 1/2 and is replaced by a half-size copy), so it is a different curve of similarity dimension log_2 3, not 1.5</source>
        <translation>článek ji nazývá Minkowského křivkou; s Minkowského klobásou se shoduje jen na úrovni 1 (její prostřední hrana má délku 1/2 a nahrazuje ji kopie poloviční velikosti), jde tedy o jinou křivku s dimenzí podobnosti log_2 3, nikoli 1.5</translation>
    </message>
    <message>
        <source>unknown normal-vector preset %1</source>
        <translation>neznámá předvolba schématu normálových vektorů %1</translation>
    </message>
    <message>
        <source>%1 needs exactly %2 control points, got %3</source>
        <translation>%1: počet řídicích bodů musí být přesně %2, zadáno %3</translation>
    </message>
    <message>
        <source>%1 needs at least %2 control points, got %3</source>
        <translation>%1: počet řídicích bodů musí být alespoň %2, zadáno %3</translation>
    </message>
    <message>
        <source>%1: the arity of a scheme must be at least 2, got %2</source>
        <translation>%1: arita schématu musí být alespoň 2, zadáno %2</translation>
    </message>
    <message>
        <source>%1: a scheme of arity %2 needs %2 rules, got %3</source>
        <translation>%1: schéma arity %2 vyžaduje počet pravidel %2, zadáno %3</translation>
    </message>
    <message>
        <source>%1: rule %2 has no weights</source>
        <translation>%1: pravidlo %2 nemá žádné váhy</translation>
    </message>
    <message>
        <source>%1: weight %2 of rule %3 is not a finite number</source>
        <translation>%1: váha %2 pravidla %3 není konečné číslo</translation>
    </message>
    <message>
        <source>%1: the weights of rule %2 sum to %3, not 1 (an affine rule must reproduce constants)</source>
        <translation>%1: součet vah pravidla %2 je %3, nikoli 1 (afinní pravidlo musí reprodukovat konstanty)</translation>
    </message>
    <message>
        <source>B-spline degree must be between 1 and 15, got %1</source>
        <translation>stupeň B-spline musí být mezi 1 a 15, zadáno %1</translation>
    </message>
    <message>
        <source>uniform B-spline of degree %1</source>
        <translation>uniformní B-spline stupně %1</translation>
    </message>
    <message>
        <source>corner cutting needs 0 &lt; a &lt; b &lt; 1, got a = %1, b = %2</source>
        <translation>ořezávání rohů vyžaduje 0 &lt; a &lt; b &lt; 1, zadáno a = %1, b = %2</translation>
    </message>
    <message>
        <source>corner cutting (%1, %2)</source>
        <translation>ořezávání rohů (%1, %2)</translation>
    </message>
    <message>
        <source>four-point tension omega is not a finite number</source>
        <translation>napětí omega čtyřbodového schématu není konečné číslo</translation>
    </message>
    <message>
        <source>four-point (omega = %1)</source>
        <translation>čtyřbodové (omega = %1)</translation>
    </message>
    <message>
        <source>Bézier degree must be between 1 and 30, got %1</source>
        <translation>stupeň Bézierovy křivky musí být mezi 1 a 30, zadáno %1</translation>
    </message>
    <message>
        <source>the de Casteljau split parameter t must lie strictly between 0 and 1, got %1</source>
        <translation>parametr de Casteljauova dělení t musí ležet ostře mezi 0 a 1, zadáno %1</translation>
    </message>
    <message>
        <source>Bézier of degree %1 (de Casteljau at t = %2)</source>
        <translation>Bézierova křivka stupně %1 (de Casteljau v t = %2)</translation>
    </message>
    <message>
        <source>end-interpolating B-spline of degree %1</source>
        <translation>B-spline stupně %1 interpolující koncové body</translation>
    </message>
    <message>
        <source>%1: an IFS needs at least two matrices, got %2</source>
        <translation>%1: IFS vyžaduje alespoň dvě matice, zadáno %2</translation>
    </message>
    <message>
        <source>%1: matrix S_1 is empty</source>
        <translation>%1: matice S_1 je prázdná</translation>
    </message>
    <message>
        <source>%1: matrix S_%2 is %3 x %4, expected %5 x %5 like S_1</source>
        <translation>%1: matice S_%2 má rozměr %3 x %4, očekáváno %5 x %5 jako S_1</translation>
    </message>
    <message>
        <source>%1: matrix S_%2</source>
        <translation>%1: matice S_%2</translation>
    </message>
    <message>
        <source>%1: matrix S_%2, row %3 sums to %4, not 1 (subdivision rows are affine combinations)</source>
        <translation>%1: matice S_%2, součet řádku %3 je %4, nikoli 1 (řádky subdivize jsou afinní kombinace)</translation>
    </message>
    <message>
        <source>the number of subdivision steps cannot be negative</source>
        <translation>počet kroků subdivize nemůže být záporný</translation>
    </message>
    <message>
        <source>classic subdivision with %1 steps would make %2 points; use fewer steps</source>
        <translation>klasická subdivize s %1 kroky by dala %2 bodů; použijte méně kroků</translation>
    </message>
    <message>
        <source>user matrices</source>
        <translation>uživatelské matice</translation>
    </message>
    <message>
        <source>the square lattice of %1 has no layout &apos;%2&apos; (it has: %3)</source>
        <translation>čtvercová mříž schématu %1 nemá rozložení „%2“ (má: %3)</translation>
    </message>
    <message>
        <source>the triangular lattice of %1 has no layout &apos;%2&apos; (it has: %3)</source>
        <translation>trojúhelníková mříž schématu %1 nemá rozložení „%2“ (má: %3)</translation>
    </message>
    <message>
        <source>%1: the mask is not symmetric under the turn of map %2 of the %3 layout</source>
        <translation>%1: maska není symetrická vůči otočení zobrazení %2 rozložení %3</translation>
    </message>
    <message>
        <source>%1: the pieces of the %2 layout are not determined by a finite net</source>
        <translation>%1: části rozložení %2 nejsou určeny konečnou sítí</translation>
    </message>
    <message>
        <source>the patch needs %1 control points on its net, got %2</source>
        <translation>plát: počet řídicích bodů na síti musí být %1, zadáno %2</translation>
    </message>
    <message>
        <source>lattice point %1 is given twice (points %2 and %3)</source>
        <translation>mřížový bod %1 je zadán dvakrát (body %2 a %3)</translation>
    </message>
    <message>
        <source>lattice point %1 (point %2) is not on the square net of the patch; missing: %3</source>
        <translation>mřížový bod %1 (bod %2) neleží na čtvercové síti plátu; chybí: %3</translation>
    </message>
    <message>
        <source>lattice point %1 (point %2) is not on the triangular net of the patch; missing: %3</source>
        <translation>mřížový bod %1 (bod %2) neleží na trojúhelníkové síti plátu; chybí: %3</translation>
    </message>
    <message>
        <source>the net has %1 lattice points but %2 control points</source>
        <translation>síť má mřížových bodů %1, ale řídicích bodů %2</translation>
    </message>
    <message>
        <source>refinement rounds must be from 0 to 12, got %1</source>
        <translation>počet kol zjemnění musí být od 0 do 12, zadáno %1</translation>
    </message>
    <message>
        <source>the mesh was refined by another scheme</source>
        <translation>síť byla zjemněna jiným schématem</translation>
    </message>
    <message>
        <source>the arity of a mask must be between 2 and 64, got %1</source>
        <translation>arita masky musí být mezi 2 a 64, zadáno %1</translation>
    </message>
    <message>
        <source>a mask needs between 1 and 4096 coefficients, got %1</source>
        <translation>maska potřebuje 1 až 4096 koeficientů, zadáno %1</translation>
    </message>
    <message>
        <source>the mask&apos;s offset %1 is absurd</source>
        <translation>posun masky %1 je nesmyslný</translation>
    </message>
    <message>
        <source>mask coefficient %1 is not a finite number</source>
        <translation>koeficient masky %1 není konečné číslo</translation>
    </message>
    <message>
        <source>the coefficients a_k with k = %1 mod %2 sum to %3, not 1: every coset of the mask must sum to 1 (the scheme must reproduce constants; the whole mask sums to the arity %2)</source>
        <translation>koeficienty a_k s k = %1 mod %2 mají součet %3, nikoli 1: každá zbytková třída masky musí mít součet 1 (schéma musí reprodukovat konstanty; celá maska má součet rovný aritě %2)</translation>
    </message>
    <message>
        <source>mask of arity %1</source>
        <translation>maska arity %1</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Subdivision curves as attractors of IFS.</source>
        <translation>Subdivizní křivky jako atraktory IFS.</translation>
    </message>
    <message>
        <source>Project file to open.</source>
        <translation>Soubor projektu, který se má otevřít.</translation>
    </message>
    <message>
        <source>Select the item with this name after opening.</source>
        <translation>Po otevření vybrat položku s tímto názvem.</translation>
    </message>
    <message>
        <source>Print the current item&apos;s figure sheet to this PDF file, then quit.</source>
        <translation>Vytisknout list s obrázkem aktuální položky do tohoto souboru PDF a skončit.</translation>
    </message>
    <message>
        <source>Save a picture of the main window to this PNG file once the attractor is drawn, then quit.</source>
        <translation>Po vykreslení atraktoru uložit snímek hlavního okna do tohoto souboru PNG a skončit.</translation>
    </message>
    <message>
        <source>Window size for --screenshot, WIDTHxHEIGHT.</source>
        <translation>Velikost okna pro --screenshot, ŠÍŘKAxVÝŠKA.</translation>
    </message>
    <message>
        <source>Export a figure of the current item to this file (.png, .svg, .pdf; .tex for the matrices), then quit.</source>
        <translation>Exportovat obrázek aktuální položky do tohoto souboru (.png, .svg, .pdf; .tex pro matice) a skončit.</translation>
    </message>
    <message>
        <source>Resolution of --export-figure in dpi (36..2400).</source>
        <translation>Rozlišení pro --export-figure v dpi (36..2400).</translation>
    </message>
    <message>
        <source>What --export-figure shows: attractor, spectrum, matrices, analysis or sheet.</source>
        <translation>Co zobrazí --export-figure: attractor, spectrum, matrices, analysis nebo sheet.</translation>
    </message>
    <message>
        <source>Size of --export-figure in pixels at its resolution, WIDTHxHEIGHT (16..20000).</source>
        <translation>Velikost pro --export-figure v pixelech při daném rozlišení, ŠÍŘKAxVÝŠKA (16..20000).</translation>
    </message>
    <message>
        <source>--export-figure without the grid.</source>
        <translation>--export-figure bez mřížky.</translation>
    </message>
    <message>
        <source>--export-figure without control polygons and start set.</source>
        <translation>--export-figure bez řídicích polygonů a počáteční množiny.</translation>
    </message>
    <message>
        <source>--export-figure framed tightly around the content (the height follows its proportions).</source>
        <translation>--export-figure těsně ohraničený kolem obsahu (výška se řídí jeho proporcemi).</translation>
    </message>
    <message>
        <source>Font of --export-figure&apos;s labels: FAMILY or FAMILY,POINTS.</source>
        <translation>Písmo popisků pro --export-figure: RODINA nebo RODINA,BODY.</translation>
    </message>
</context>
</TS>
