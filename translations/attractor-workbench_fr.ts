<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR" sourcelanguage="en">
<context>
    <name>ExportDialog</name>
    <message>
        <source>Export Figure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The view or figure to export.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attractor view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spectrum plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analysis chart (current tab)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Figure sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File to write; its suffix (.png, .svg or .pdf; .tex for the matrices as LaTeX) picks the format.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the file to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The suffix picks the format: .png, .svg or .pdf (the Matrices view also .tex: LaTeX bmatrix).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Width:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Width of the figure in pixels (for SVG and PDF: pixel units at the resolution below).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> px</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Height:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Height of the figure in pixels (for SVG and PDF: pixel units at the resolution below).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Resolution:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resolution in dots per inch (dpi).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> dpi</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw the coordinate grid and its labels (when the view shows them).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw the control polygons, the start set and their points and labels.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frame the attractor view&apos;s content tightly: the height follows the content&apos;s proportions (the width is kept).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;rop to contents</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F&amp;ont:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Font of the labels and of the figure sheet&apos;s text.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Label size in points as the figure is shown at its resolution (0: as on screen).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as on screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> pt</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default &amp;depth of new items:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deterministic depth given to new items.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Maximum drawn depth:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw at most this depth, whatever the item asks for.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Map &amp;colours:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour of map 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour of map 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour of map 3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour of map 4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour of map 5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour of map 6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use the views&apos; default colours for all maps.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Autosave interval:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time between automatic saves of a recovery copy of the project, in seconds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>%1, Hölder regularity r in [%2, %3] (width %4)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::AddressPanel</name>
    <message>
        <source>Address 0,1,1 or interval [0.25, 0.5]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An address selects the sub-copy f_w(A) = f_w1(f_w2(…(A))): map numbers from 0, the outermost map first. A subdivision curve also takes a parameter interval [t0, t1]. Enter selects, an empty field clears.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click the attractor to pick an address; click a symbol of it to select that prefix.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>address %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, t ≈ %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clicked: %1&lt;br&gt;&lt;small&gt;click a symbol to select the prefix up to it&lt;/small&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The item drawn has no addresses to select (only items drawn by one IFS in the plane have).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a parameter interval selects on a subdivision curve with a real parameter; this item has none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t in %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;t in %1&lt;/b&gt; (%2)&lt;br&gt;Pieces inside it (addresses up to 8 symbols): %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;br&gt;The control polygons of the first %1 pieces are drawn.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>w = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;w = %1&lt;/b&gt;: the sub-copy f_w(A) = %2(A)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>   t in [%1, %2]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;br&gt;t in [%1, %2] (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;br&gt;Control points S_w P = %1 (symbol i is S_(i+1)):&lt;br&gt;%2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::AlgorithmSpec</name>
    <message>
        <source>the depth cannot be negative, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth %1 is absurd: at most %2 is allowed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth %1 with %2 maps makes %3 images of the start set, more than 2^31; use a smaller depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the sample count must be between 1 and 2^31, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the seed must be between 0 and 2^53 - 1, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>probability %1 must be a finite number &gt;= 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the probabilities sum to 0</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::AnalysisCharts</name>
    <message>
        <source>Distance to the exact curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control polygon length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Box counting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Eigenvalue moduli</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>|λ| per map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;depth k = %2&lt;br&gt;d&lt;sub&gt;H&lt;/sub&gt; = %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;step k = %2&lt;br&gt;length = %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;log(1/ε) = %2 (ε = %3)&lt;br&gt;log N(ε) = %4 (N = %5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;|λ| = %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>∝ %1^k</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth k</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hausdorff distance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control polygon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>exact curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>subdivision step k</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Box counting: dimension D = %1, R² = %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Box counting: no fit (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not fitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fitted levels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fit: log N = %1 log(1/ε) + %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>log(1/ε)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>log N(ε)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>|λ| = 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>|λ|</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::Animation</name>
    <message>
        <source>expected a duration in seconds above 0 and at most %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected between 1 and %1 frames per second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 s at %2 frames per second makes more than %3 frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>names no parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is driven by an earlier track already</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>needs at least one key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a time between 0 and the duration, %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>key times must increase (%1 s follows %2 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected %1 numbers, as the first key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a circle turns a point or a complex value, not one number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected [x, y]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a number of turns between -1000 and 1000</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probabilities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points %1, point %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control point %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no probabilities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no control point %2 in point set %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a number that can be animated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no parameter %2 (now)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no such control point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the point was refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no such parameter now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a complex value needs 2 numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 at %2 s: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the value was refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has %2 coordinates, the keys %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>p = (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1 s: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of tracks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an object {&quot;time&quot;, &quot;value&quot;}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown field of a key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown field of a track</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown field of an animation</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::AnimationPanel</name>
    <message>
        <source>Play / pause the animation (Ctrl+Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop: the views show the item itself again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time: drag to see the frames (the views follow)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time and frame number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duration of the animation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> fps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter / key time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double-click a key&apos;s time or value to edit it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The parameter, probabilities or control point to key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store the item&apos;s present value of the parameter at the time shown (replaces a key at that time)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the selected key, or the selected track with its keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Linear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smooth (ease in and out)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Through the keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Circle about a centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x, y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interpolation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The views show the item itself.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 s · %2/%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frame at %1 s: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The views show the frame at %1 s (not editable); Stop returns to the item.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No item is selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a key or a track to remove.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inactive: %1 has no such input now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>circle about (%1), %2 turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The item does not have %1 in its present state (another scheme, fewer points): the track is kept and skipped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select an item to animate its parameters.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No keys yet: set a value in Properties, choose it here and press Set Key; then move the slider, change the value and key it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no numeric parameters to animate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 tracks, %2 frames. Play or drag the slider to preview.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a time in seconds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot;: expected %2 numbers</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::AttractorItem</name>
    <message>
        <source>Change start set of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change algorithm of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Remove %n control points of %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>map %1 is not finite: the control points&apos; coordinates overflow in the lifted map P⁻¹ S_i P (the largest is %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the start set is not finite in the IFS space: the lifting overflows (the largest control point coordinate is %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lifted start points need an invertible lifting: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a lifted start point of this item has %1 coordinates (x, y and the %2 extra coordinates of the lifting, the homogeneous 1 implied); point %3 has %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 points; an item takes at most %2 (its subdivision matrices would be %1 x %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>point set %1 has %2 points; an item takes at most %3 per set</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::AttractorRenderer</name>
    <message>
        <source>Cannot draw the attractor: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::AttractorView</name>
    <message>
        <source>Rendering… %1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rendering cancelled at %1 % — press F5 to render again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F^%1(X₀) has too many images to draw as vectors</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::BcifsJunctionItem</name>
    <message>
        <source>Junction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change junction of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e = %1, p = %2 (column sums). %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a junction is drawn by an automaton, not by one lifted IFS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubic–quadratic (003 §4.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refined, with handles (003 §5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last column (a, b, c, d, e) of T^l; e = 1 − a − b − c − d (003 §4.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First column (k, l, m, n, p) of T^r; p = 1 − k − l − m − n (003 §4.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left eigenvalue j</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tangent eigenvalue of T^il (003 §5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right eigenvalue r</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tangent eigenvalue of T^ir (003 §5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>BCIFS junction curve</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::BezierUnionItem</name>
    <message>
        <source>Bézier union</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 split parameters for %2 curves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Bézier union %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>curve %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>curves drawn in the lifted space of 000 §2: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every composition of %1 maps contracts (factor %2): the dusty fractal of 002 §6 is the unique attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no contraction was proven (best bound %1 at length %2): the picture may not be an attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a non-empty array of curves {&quot;control_points&quot;: [...], &quot;u&quot;: number}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an object with &quot;control_points&quot; and &quot;u&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Union</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exact union (block IFS, 000 §2.2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All maps together (dusty fractal, 002 §6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Split parameter u</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Curve %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>de Casteljau split at u, 0 &lt; u &lt; 1 (002 eqs. (9)-(10)); the curve is the same for every u, the IFS is not</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Union of Bézier curves</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::BezierUnionSpec</name>
    <message>
        <source>a union needs at least one curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the split parameter u = %1 must satisfy 0 &lt; u &lt; 1 (002 §3)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::CifsItem</name>
    <message>
        <source>Fern of gaskets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change automaton of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the frame needs exactly 3 points, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a controlled IFS has no single lifted IFS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc T%1 of the fern leads into the Sierpiński state (003 §2.2, Fig. 4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automaton</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redirected arc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The fern map (0 stem, 1 main frond, 2 left, 3 right leaflet) whose arc leads into the Sierpiński state (003 Fig. 4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawn state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The state whose attractor is drawn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controlled IFS</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::CifsSpec</name>
    <message>
        <source>the redirected fern arc must be 0 … 3 (T0 … T3), got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no state &quot;%1&quot;; the states are &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ComplexBezierItem</name>
    <message>
        <source>Complex Bézier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the parameter t must be a finite complex number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change t of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected [re, im]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Split parameter t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>de Casteljau split at a complex t; inside both discs |t| &lt; 1 and |1 − t| &lt; 1 the curve is a fractal (004 §3.7, Fig. 3.3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid value for %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complex Bézier curve</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ComplexPlanePicker</name>
    <message>
        <source>Drag t in the complex plane. The attractor exists inside the lens where |t| &lt; 1 and |1 − t| &lt; 1 (both maps contract, 004 Fig. 3.3).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ControlPointEdits</name>
    <message>
        <source>There is no such point set.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2) has a fixed number of control points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A Bézier curve of degree %1 is refused: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no point %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert control point %1 into %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No control point is selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs at least %2 control points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete control point %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete %1 control points of %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::EigenvaluePlotItem</name>
    <message>
        <source>Eigenvalues</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S_i, the subdivision matrices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A_i, the linear parts of M_i</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>M_i = P⁻¹S_iP, the lifted maps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the source of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analyse the matrices %1 in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>M_i is defined only for a lifted subdivision IFS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no item is chosen to analyse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is no item called &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; (%2) has no matrices to analyse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be computed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no matrices %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Eigenvalue plot</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ExactCurve</name>
    <message>
        <source>Bézier curve c([0, 1])</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takagi image c(x + 2iy·T(x)), y = %1 (Conj. 3.7.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>exact curve: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ExportDialog</name>
    <message>
        <source>Export Figure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;LaTeX matrices (*.tex)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::FieldReader</name>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a string</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected one of %1, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an integer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an integer between %1 and %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of points [x, y, z]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of points [x, y]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of matrices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a matrix: a non-empty array of rows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a row: a non-empty array of numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>row %1 has %2 numbers, row 1 has %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be read as a double-precision number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a point [x, y, z]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a point [x, y]</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::FigureFile</name>
    <message>
        <source>cannot write %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the folder %1 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write %1: it is a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no suffix: name the format (.png, .svg or .pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown output format &apos;.%1&apos; (use .png, .svg or .pdf)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::FigureMetadata</name>
    <message>
        <source>%1: cannot read the PNG: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>larger than 512 MB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: this PNG holds no Attractor Workbench item (only figures exported by Attractor Workbench carry their parameters)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::FigureSheet</name>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>maps = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>samples = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 × %3 (see the Matrices dock)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>… and %n more: see the Matrices dock, or copy them as LaTeX.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Printing %1 was cancelled while the attractor was drawn.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::FileWriting</name>
    <message>
        <source>the folder %1 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot create a file in the folder %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the folder %1 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is not open</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::FractalItem</name>
    <message>
        <source>expected an array of %1 numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing (the custom form needs its maps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a non-empty array of maps {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an object with &quot;A&quot; and &quot;b&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a 2 x 2 matrix [[a11, a12], [a21, a22]]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the custom form needs at least one map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map %1 is not a map of the plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map %1 has a non-finite entry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a reference point is not finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>need at least 3 reference points (000 §4), got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fractal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change fractal of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 reference points and the %2 control points must be equally many</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the reference points are ill-conditioned: S_i R differs from f_i(R) by up to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Koch curve (000 §4.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sierpinski triangle (000 §4.2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Own maps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The presets use the paper&apos;s printed matrices S_i</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Affine weights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nearest control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Least norm (all points)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How f_i(P_j) is written as an affine combination of the control points (000 eq. (5)): nearest points keep edits local, least norm lets every point move the whole fractal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fractal with control points</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::InsertControlPointCommand</name>
    <message>
        <source>Add a control point to %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::InsertItemCommand</name>
    <message>
        <source>Add %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::Item</name>
    <message>
        <source>Rename</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change style of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit animation of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the name cannot be empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid value for %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>circular reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is not enough memory to compute it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ItemAddress</name>
    <message>
        <source>t: the B-spline&apos;s knot parameter scaled to [0, 1] (the address in base 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t: the knot parameter scaled to [0, 1] (the address in base 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t: the Bernstein parameter (the address in base 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t: the Bernstein parameter (pieces [0, t], [t, 1] of the split)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t: the scheme&apos;s own parameter, the address read in base %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this item is drawn by an automaton: its words are not addresses of one IFS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a parameter interval is [t0, t1] with two numbers, e.g. [0.25, 0.5]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the parameter interval [%1, %2] must satisfy 0 &lt;= t0 &lt; t1 &lt;= 1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ItemController</name>
    <message>
        <source>%1 shows nothing: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no attractor to draw.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be drawn: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start set: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Regularity: only for subdivision curves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Regularity: does not apply (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>complex de Casteljau parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the scheme&apos;s parameters are refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F^k(X0) to the %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F^k(X0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changing %1 (%2, %3) from %4 to %5 makes row %2 sum to %6, not 1: the rows of a subdivision matrix are affine combinations.

Take the difference %7 from the entry in column %8 (%9 → %10) so that the row sums to 1?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2, %3) = %4 was refused: %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert Point &amp;Before %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert Point &amp;After %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Point %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Insert Point Here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Append Point Here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fit View</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::JunctionSpec</name>
    <message>
        <source>the junction parameter %1 must be a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 = %2 is outside (%3, %4): %5</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::MainWindow</name>
    <message>
        <source>Attractor Workbench projects (*.awb);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;original&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel the analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawing %p%</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop drawing the attractor (Esc); F5 draws it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawing the attractor for the figure…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Figure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawing stopped; press F5 to draw again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analysis %p%</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analysis cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Row sum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x = %1, y = %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawing failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Print…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print Pre&amp;view…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+Shift+P</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print to P&amp;DF…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print to PDF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export Figure…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;Points…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pre&amp;ferences…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy Matrices as &amp;LaTeX</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+Shift+L</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The current item has no matrices.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Copied %n matrices as LaTeX (amsmath bmatrix).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>D&amp;uplicate Item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+D</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Stop Drawing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Draw Again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Play/Pause Animation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;top Animation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About Attractor Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Control Polygon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control &amp;Net (3D)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subdivided &amp;Mesh (3D)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Attractor (3D)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A&amp;xes (3D)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Bounding Box (3D)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Perspective (3D)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start Set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Exact Curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Properties</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo History</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spectrum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Animation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Four-point &amp;Regularity Chart…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Main</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Hutchinson step: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw F^k(X0) of the start set X0 as vectors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  Subdivision steps: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Classic subdivision polygons beside the IFS attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1[*] — Attractor Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cubic B-spline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project &quot;%1&quot; has unsaved changes. Save them?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Projects and figures with their item (*.awb *.png);;Attractor Workbench projects (*.awb);;Exported figures (*.png);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Revert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard all changes and reload %1?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Printing cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The printer could not be started.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A .tex file holds the matrices only: choose the Matrices view, or .png, .svg or .pdf for a picture.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The current item has no matrices to export.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown format &quot;%1&quot;: use .png, .svg or .pdf (.tex for the matrices).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exporting %1 was cancelled while the attractor was drawn.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About Attractor Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attractor Workbench %1

Subdivision curves as attractors of iterated function systems: control points, subdivision matrices, spectra and figures.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spectra of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bicubic B-spline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop (box spline)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kobbelt √3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, %2 layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>duplicate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duplicate Item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an unsaved project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recover Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attractor Workbench did not shut down properly. A recovery copy of %1 from %2 exists. Recover it? (Discard deletes the copy.)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The recovery copy cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The recovery copy cannot be read: %1

It was kept as %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The current item has no attractor whose points could be exported.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported the points to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The current item has no attractor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System Default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The language changes when Attractor Workbench is started again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Built with Qt %1 (running on Qt %2), Eigen %3 and QCustomPlot %4.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::MatrixHeatMap</name>
    <message>
        <source>%1 (%2, %3) = %4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::MatrixView</name>
    <message>
        <source>%1 %2 %3i (modulus %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sum of row %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sum of column %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” is not a finite number: %2, row %3, column %4 was not changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>b row</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fixed part of the lifted map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>— &lt;span style=&apos;background:#e2ecfa&apos;&gt;&amp;nbsp;A&amp;nbsp;&lt;/span&gt; block, &lt;span style=&apos;background:#fcecd6&apos;&gt;&amp;nbsp;b&amp;nbsp;&lt;/span&gt; row</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(complex entries)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::MoveControlPointsCommand</name>
    <message numerus="yes">
        <source>Move %n control points of %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>awb::MoveItemCommand</name>
    <message>
        <source>Move %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::NormalVectorItem</name>
    <message>
        <source>Normal-vector curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change normal-vector scheme of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the normal-vector scheme is not linear: it has no subdivision matrices (001 eq. (1))</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No equivalent IFS: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of sign rules</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected one of &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Own rules</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subdivision steps of the polygon shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Counter-clockwise (positive)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clockwise (negative)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed polygon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>α%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rules</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position of new point %1 along the edge (001 eq. (1))</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>β%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Displacement of new point %1 along the normal</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::NormalVectorSpec</name>
    <message>
        <source>unknown preset &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 steps: at least 0 and at most %2 are allowed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>need at least 2 rules (p &gt;= 2), got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 values of beta for %2 of alpha: need one per rule</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 signs for %2 rules: give none, one, or one per rule</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1_%2 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::PaletteDialog</name>
    <message>
        <source>Map Colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The colour of the points each map f&lt;sub&gt;i&lt;/sub&gt; makes (Style: colour by map or by address).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour of map %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Map %1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use the &amp;Default Colours</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::PointExport</name>
    <message>
        <source>cannot write the points: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--address needs an item drawn by one IFS; this one is drawn by an automaton</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is drawn by an automaton: PLY export covers items with one IFS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wrote %1 points, expected %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::PointExportDialog</name>
    <message>
        <source>Export Points of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV text: x, y[, z], map, view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLY point cloud: x, y, z, map colour, map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F&amp;ormat:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The points of F^k(X0): every image of the start set&apos;s vertices after k steps of the Hutchinson operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Depth k:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV text (*.csv);;PLY point cloud (*.ply)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The number of points depends on the automaton.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — too many (at most %1): choose a smaller depth.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be computed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start set: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth %1 gives %2 points, more than %3: choose a smaller depth.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing the points of %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exporting the points was cancelled; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::PreferencesDialog</name>
    <message>
        <source>auto</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::Project</name>
    <message>
        <source>Item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the name cannot be empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another item is already called &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Remove %n items</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the project has no file name yet: use &quot;Save As&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ProjectIO</name>
    <message>
        <source>%1: cannot save: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the file is %2 MB; project files larger than %3 MB are refused (a project is at most a few MB)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the file is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the file holds only white space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the file is UTF-16 or UTF-32 text; project files are UTF-8 (save it again as UTF-8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: expected a JSON object at the top level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not valid JSON: %2 at line %3, column %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected &quot;%1&quot;: this is not an Attractor Workbench project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the file has format version %2, written by a newer version of Attractor Workbench; this version reads format version %3 only. Please update the application.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;%2&quot;: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2: field &quot;%3&quot;: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>field &quot;%1&quot;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown item type %1; this version knows %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another item is already called %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of items</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of lifted points [x, y, c1, ...]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a lifted point [x, y, c1, ...]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of &quot;#rrggbb&quot; strings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected a string &quot;#rrggbb&quot;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ProjectTreeModel</name>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Move %n items</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>awb::PropertiesWidget</name>
    <message>
        <source>Value refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be set to %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No item selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The name is empty or already taken.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Im </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start set X0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lifted points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drag its vertices in the attractor view.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Points of the lifted space of 000 §2: x, y, then the extra coordinates of the lifting, the homogeneous 1 implied. Commas between coordinates, &apos;;&apos; between points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lifted:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The start set was refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The item has no control points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Algorithm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deterministic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Random (chaos game)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Style</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>By map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>By address prefix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Single colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Prefix length:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point size:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a finite number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Append a point after the last one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert a point before the selected one (halfway to its predecessor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the selected points (one undo step)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The colour of each map&apos;s points: click to choose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Own…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Map colours:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Eigenvalues</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The item whose matrices are analysed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S_i: the subdivision matrices (their eigenvalue 1 is affine invariance); A_i: the linear parts of the lifted maps, whose subdominant eigenvalue decides the tangents; M_i: the lifted maps themselves (003 §4, 004 §2.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Matrices:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (missing)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 matrices %2_i, %3 eigenvalues: see the Spectrum and Matrices panels.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::Recovery</name>
    <message>
        <source>%1: cannot open: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not an Attractor Workbench recovery file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: written by a newer version of Attractor Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;project&quot;: expected an object</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::RegularityChart</name>
    <message>
        <source>Regularity of the four-point scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Certified Hölder regularity r(ω) of the four-point scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lower bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>upper bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>known: ω = 0 → 1, ω = 1/16 → 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tension ω</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>regularity r (C^n for n &lt; r)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing %1 values of ω…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 values of ω; widest interval %2 (bounds certified; the upper bound is exact for this interpolatory scheme)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::RegularityPanel</name>
    <message>
        <source>Regularity: no curve scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Regularity %p%</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the regularity analysis; the bounds reached so far stay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Regularity of %1: computing…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>so far: r in [%1, %2]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Regularity: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::RemoveControlPointCommand</name>
    <message>
        <source>Remove a control point of %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::RemoveItemCommand</name>
    <message>
        <source>Remove %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::SchemeRegularity</name>
    <message>
        <source>does not apply: a complex de Casteljau parameter is not a real subdivision scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>does not apply: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::SpectrumView</name>
    <message>
        <source>Re λ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Im λ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unit circle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dominant 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>subdominant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: λ = %2, |λ| = %3, multiplicity %4, arg λ = %6° (map %5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — dominant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — subdominant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;No maps.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;All maps are (eventually) contractive&lt;/b&gt;: the IFS has a unique attractor.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;%1 is not contractive&lt;/b&gt;: the IFS has no attractor and its iteration does not converge.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not contractive: spectral radius %1 ≥ 1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contractive: ‖A‖&lt;sub&gt;2&lt;/sub&gt; = %1 &amp;lt; 1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Eventually contractive: spectral radius %1 &amp;lt; 1, ‖A&lt;sup&gt;%2&lt;/sup&gt;‖&lt;sub&gt;2&lt;/sub&gt; &amp;lt; 1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Eventually contractive: spectral radius %1 &amp;lt; 1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No subdominant eigenvalue: the map is constant.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>real positive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The curve has a half-tangent at the fixed point, along the eigenvector (G¹ where the two sides&apos; eigenvectors align).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repeated: the tangent direction at the fixed point depends on the control points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>real negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The curve oscillates at the fixed point and has no tangent there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>complex pair</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The curve spirals around the fixed point (no tangent).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>complex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Near the fixed point the map acts as the spiral similarity z ↦ λz: the curve spirals around the fixed point (no tangent).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mixed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Several eigenvalues of the same modulus with different signs or phases: no single tangent behaviour.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subdominant: none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subdominant: %1 (%2, |λ| = %3, multiplicity %4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown file type “%1”: use .pdf, .svg or .png.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Eigenvalues</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::StartSetSpec</name>
    <message>
        <source>a lifted start set needs at least one point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lifted start point %1 has %2 coordinates: every point needs the same number, at least 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every point must have finite coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a start set of kind &quot;%1&quot; needs exactly %2 points, got %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a start set of kind &quot;%1&quot; needs at least %2 points, got %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::StyleSpec</name>
    <message>
        <source>the density gamma must be between 0.2 and 10, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the address prefix length must be between 1 and %1, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the point size must be more than 0 and at most %1 pixels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>colour %1 is &quot;%2&quot;, expected &quot;#rrggbb&quot; (lower-case hexadecimal)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionCurveItem</name>
    <message>
        <source>Bézier of degree %1 needs exactly %2 control points, got %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a complex Bézier parameter has no real scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown scheme kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the complex parameter t = %1 %2 %3i must satisfy |t| &lt; 1 and |1 - t| &lt; 1 (004 §3.7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change scheme of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected [re, im] or a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Uniform B-spline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End-interpolating B-spline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner cutting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Four-point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bézier (de Casteljau)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Own matrices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree n: the curve has n + 1 control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree of the B-spline (Lane–Riesenfeld, 004 eq. 2.7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Split parameter t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>de Casteljau split at t (004 eq. 2.5). A complex t inside both discs |t| &lt; 1, |1 − t| &lt; 1 gives a fractal curve (004 §3.7).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tension ω</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1/16 gives C1 curves reproducing cubics; −1/2 &lt; ω &lt; 0 or 1/4 ≤ ω &lt; 1/2 gives fractal curves (004 Thm. 2.4.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New points at parameters a &lt; b on every edge (Chaikin: 1/4, 3/4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First cut a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Second cut b</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subdivision curve</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionSurfaceItem</name>
    <message>
        <source>Surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change net of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change subdivision rounds of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turn the view of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected an array of lattice coordinates [i, j]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected lattice coordinates [i, j]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lattice coordinates are whole numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at least one map must be used (leave the field out to use all)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map indices are whole numbers (0-based)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the elevation must be from -90 to 90 degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bicubic B-spline (Catmull–Clark)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop (three-direction box spline)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kobbelt √3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A new scheme starts from its own default net (000 §3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The patch&apos;s domain and the maps covering it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Map %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leave maps out to draw a fractal lying on the surface (000 Fig. 9)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Azimuth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction of the orthographic camera around the z axis, in degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Elevation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Height of the camera above the xy plane, in degrees</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subdivision rounds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rounds of classic subdivision of the net (000 Figs. 6–8, top)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>from 0 to %1 rounds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at least one map must stay on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subdivision surface</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::SurfaceNet</name>
    <message>
        <source>every control point must have finite coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 lattice coordinates for %2 control points: give one [i, j] per control point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not the net of a %1 %2 patch: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map %1 does not exist: the %2 layout has maps 0 to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>list each map once, in increasing order (0-based)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::SurfaceSchemeSpec</name>
    <message>
        <source>the %1 scheme has the layouts %2, not &apos;%3&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::SurfaceView</name>
    <message>
        <source>Drawing… (CPU renderer)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CPU renderer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::UserGuideDialog</name>
    <message>
        <source>Attractor Workbench — User Guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;The guide is missing.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home or F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the attractor view to its content</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>+ / −</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom the attractor view in / out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mouse wheel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom at the cursor (view); scroll (panels)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::analysis</name>
    <message>
        <source>cannot index an empty point set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>point sets must have 1 to 3 coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>point set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>point sets of different dimensions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>too few points for box counting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all points coincide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not enough points for three box sizes with at least %1 points per box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the joint spectral radius needs at least one matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the joint spectral radius needs square matrices of one size; matrix %1 differs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>matrix %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not convergent: the first difference scheme does not contract (JSR &gt;= 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>convergence not certified within the time budget</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C^%1, Hölder regularity in [%2, %3]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled; the bounds are those reached. </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time budget spent; the bounds are those reached. </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not convergent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C^0 not certified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the arity of a scheme must be at least 2, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the mask has a coefficient that is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no difference scheme: the mask is zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no difference scheme: the symbol a(z) has no factor 1 + z%1 (the rules&apos; weights do not each sum to 1), so the scheme does not reproduce constants and is not convergent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not convergent: the mask sums to %1, not the arity %2 (the scheme does not reproduce constants)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the upper bound is the exact Hölder exponent only if the integer shifts of the basic limit function are stable (not checked for this mask). </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>regularity needs at least two subdivision matrices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the subdivision matrices must all be square and of one size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>matrix S_%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no difference scheme: the rows of S_%1 do not all sum to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no regularity: S_1 or S_p has no simple eigenvalue 1, so the curve&apos;s end points are not defined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no regularity: the pieces S_%1 and S_%2 do not join (the attractor is not a continuous curve in its %3-adic parameter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C^infinity: the curve is one polynomial piece of degree %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the matrices reproduce every polynomial of degree &lt; %1 in the %2-adic parameter and leave no complement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the upper bound assumes the curve&apos;s basis functions are stable. </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the pieces join only C^%1 (derivative %2 differs across a join). </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C^infinity: a Bézier curve is a polynomial of degree %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>de Casteljau subdivision reproduces the Bézier polynomial exactly</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>eigenvalues need a square matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the eigenvalue computation did not converge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no subdominant eigenvalue (the map is constant)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>real positive: the curve has a half-tangent at the fixed point, along the eigenvector (G1 where the two sides&apos; eigenvectors align)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>real positive but repeated: the tangent direction at the fixed point depends on the control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>real negative: the curve oscillates at the fixed point and has no tangent there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>complex pair: the curve spirals around the fixed point (no tangent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>complex: near the fixed point the map acts as the spiral similarity z -&gt; lambda z, so the curve spirals around the fixed point (no tangent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>several eigenvalues of the same modulus with different signs or phases: no single tangent behaviour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not contractive: spectral radius %1 &gt;= 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>contractive (factor ||A||_2 = %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>eventually contractive (spectral radius %1 &lt; 1; ||A^%2||_2 &lt; 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>eventually contractive (spectral radius %1 &lt; 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map %1 is not contractive: the spectral radius of its linear part is %2 &gt;= 1, so the IFS has no attractor (the iteration does not converge)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::cli</name>
    <message>
        <source>Render the bundled paper figures to PNG files (one row of panels per figure: the start set, a few iterates of the Hutchinson operator, and the attractor, over the control polygon).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Directory for the PNG files (created if missing).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>List the examples and exit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attractor-cli: cannot create directory %1</source>
        <translation type="unfinished"></translation>
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
  export     attractor points as PLY, a surface&apos;s subdivided net as OBJ
  polygon    the control polygon after K subdivision steps (JSON)
  examples   render the built-in paper figures (000 Figs. 2, 3, 5) to PNG

Run &apos;attractor-cli &lt;command&gt; --help&apos; for the options of a command.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attractor-cli: unknown command &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected %1 project file, got %2 arguments (see --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no item named &apos;%1&apos; in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the figure&apos;s project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no item with an attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--%1 must be a whole number from %2 to %3, got &apos;%4&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--%1 must be a number from %2 to %3, got &apos;%4&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--start: &apos;%1&apos; is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--start must be point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;..., got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--start %1 needs %2 coordinates (%3 per point), got %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a multiple of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth %1 gives %2 points, more than --max-points %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Image size in pixels (default 900x700).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deterministic iteration depth (default: the item&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Random iteration with this many points (up to 1e12; memory stays that of the raster).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Raster tone: &apos;hits&apos; (every lit pixel opaque, the papers&apos; look) or &apos;density&apos; (log density of the invariant measure, gamma and vibrancy as flame renderers). Default: the item&apos;s style (auto: hits for deterministic, density for random iteration).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Density tone: display gamma (default: the item&apos;s, 2.2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Density tone: 1 saturated colours, 0 per-channel gamma (default 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Histogram cells per pixel side, 1..4 (default 1; 2 or 3 anti-alias edges).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Threads of the raster engine (default: all cores).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Surfaces: the camera&apos;s azimuth and elevation in degrees (orthographic; default: the item&apos;s camera).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plane figures: the world rectangle to frame (padded by 6%), e.g. to compare figures at one scale (default: fit the content).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The output&apos;s format when its name has no suffix (e.g. /dev/stdout): png, svg or pdf (default: the suffix).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--depth and --samples exclude each other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--size must be WxH with 64..16384 pixels each, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--tone must be &apos;hits&apos; or &apos;density&apos;, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--bounds must be x0,y0,x1,y1 with x0 &lt; x1 and y0 &lt; y1, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--format must be png, svg or pdf, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth %1 makes %2 images; at most 4e9 are rendered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--view must be AZ,EL in degrees with |EL| &lt;= 90, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 random points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F^%1(X0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, maps %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2%3 — orthographic view from azimuth %4°, elevation %5°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 random points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: F^%2(X0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: polygon after %2 steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Render an item&apos;s attractor (with its control polygons) to PNG, SVG or PDF.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The .awb project file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The item to render (default: the first with an attractor).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output file: .png, .svg or .pdf.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--out FILE is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Render the frames of an item&apos;s animation (its keyframed parameters): numbered PNG files in a folder, or an MP4 or GIF movie through ffmpeg. Frame k is the item with its parameters at time k / fps, drawn exactly as `render` draws it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The animated item (default: the first item with an animation).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A folder for frame-0000.png, frame-0001.png, ... (made if missing), a movie .mp4 or .gif (made by ffmpeg), or with --frame one .png/.svg/.pdf.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames per second (default: the animation&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Render only frame K (0 = the start) to the file --out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Captions without the frame&apos;s time and values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--out DIR|FILE is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no animated item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item &apos;%1&apos; has no animation: key its parameters in the Animation dock, or give it an &quot;animation&quot; field (docs/file-format.md)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>attractor-cli: note: the track of %1 is skipped: item &apos;%2&apos; has no such input now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1,%2,%3,%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fitted per frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frame %1 (t = %2 s): %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing %1 needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg); give --out a folder to get the frames as PNG files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot make a temporary folder for the frames: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a file, not a folder (a movie needs .mp4 or .gif)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot make the folder %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frame-%1.png</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ffmpeg could not write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 frames of %3x%4 at %5 frames/s (%6 s); rendered in %7 s, %8 frames/s
bounds: %9
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analyse the items of a project: per map S_i (exact fractions), M_i = P^-1 S_i P with its blocks A_i, b_i, the eigenvalues of S_i and A_i, spectral radius, contractivity and fixed point; per item the subdominant eigenvalues, the Hausdorff distance to the exact curve and the box-counting dimension; per subdivision curve the certified Hölder regularity of its scheme.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only this item.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print JSON (the only format so far).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--json is required (the only output format)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the points of F^k(X0) as CSV: x, y (and z for a surface), the map applied last (1-based), and the view. --address w limits them to the sub-copy f_w(A): the points f_w(F^k(X0)).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The item.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Iteration depth (default: the item&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start set: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (plane coordinates; x,y,z for a surface) | lifted:x,y,c1,...;x,y,c1,... (points of the lifted space of 000 §2; default: the item&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print CSV (the only format so far).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only the sub-copy f_w(A) of this address: 0-based map numbers, w_1 (the outermost map) first, e.g. 0,1,1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refuse to print more (default 10000000).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--item NAME is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--csv is required (the only output format)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--address %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--start lifted: needs at least one point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write to the standard output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validate a project file: it must load, and every item&apos;s IFS must be computable (exit 1: the file is refused; exit 3: it loads but items cannot be computed).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2: note: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load a project and save it again in the canonical form of this version (sorted keys, every field written): to upgrade or normalise a hand-written file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write here instead of over the input.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>v %1 %2 %3
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), or a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ply (attractor points) or obj (subdivided mesh).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLY: iteration depth (default: the item&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OBJ: rounds of subdivision (default: the item&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLY: refuse to write more (default 50000000).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj and --out FILE are required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--format must be ply or obj, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is drawn by an automaton: PLY export covers items with one IFS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OBJ export writes the subdivided net of a surface item; &apos;%1&apos; is a %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the control polygon after K subdivision steps as JSON {&quot;closed&quot;, &quot;points&quot;}: the figures of 001 for a normal-vector item (eq. (1) applied K times), classic subdivision S_w P for a subdivision curve.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subdivision steps K (0: the control polygon).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print JSON (the only format).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item &apos;%1&apos; has a complex split parameter: its control polygon has complex points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>level %1 gives more than 5e7 points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) is not polygon-based: the polygon command takes normal-vector items and subdivision curves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing to draw</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::core</name>
    <message>
        <source>%1: entry (row %2, column %3) is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>matrix rows of different lengths</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::ifs</name>
    <message>
        <source>the IFS has 1 map (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the IFS has %1 maps (0..%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no parameter intervals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a parameter interval is empty or not finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the address has %1 symbols, more than %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>symbol %1 of the address is map %2, but %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the IFS has no maps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the address &apos;%1&apos; has an empty symbol (a comma too many)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the address &apos;%1&apos; ends with a comma</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the address is empty: give map numbers such as 0,1,1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>symbol %1 of the address, &apos;%2&apos;, is not a map number (0-based whole number)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no subdivision matrices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the subdivision matrices differ in size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the parameter %1 is outside [0, 1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an address has 0..%1 symbols</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the parameter interval must satisfy 0 &lt;= t0 &lt; t1 &lt;= 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the seed point has %1 coordinates, the IFS %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map 0 does not converge to a fixed point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>iteration depth must be between 0 and %1, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the start set is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start set has %1 coordinates, the IFS space has %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at most 255 maps are supported, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no sink to receive the attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start point has %1 coordinates, the IFS space has %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at most %1 random-iteration samples, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>column %1 of %2 sums to %3, not 1: it does not map barycentric points to barycentric points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the BCIFS has no cell &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the BCIFS has no operator &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the BCIFS has no cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cell &apos;%1&apos; has dimension %2; it needs at least one control point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operator &apos;%1&apos; joins a cell that does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operator &apos;%1&apos; (%2 -&gt; %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 joins cells of the wrong kinds: subdivisions join edges or vertices, boundary operators go from an edge to a vertex, placements from the model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is %2; it must be %3 x %4 (column convention: rows = dimension of &apos;%5&apos;, columns = dimension of &apos;%6&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edge cell &apos;%1&apos; has no subdivision operator: its attractor would be empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>constraint %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has an empty side or an unknown operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 ends at &apos;%3&apos; but %4 starts at &apos;%5&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2) compares paths between different cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 constraint %2 %3 is violated by %4 (entry row %5, column %6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; also violated:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edge cell &apos;%1&apos; has no placement (control points): it cannot be drawn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the junction matrix must be square and at least 2 x 2, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the copy&apos;s placement must have %1 rows (one per control point of the junction), got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the junction has %1 control points, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>junction matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>copy placement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the junction matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the copy placement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the copies collapse onto the fixed point: no tangent information</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lambda = %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; |lambda| &gt;= 1, so the junction matrix does not contract</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (the copy has no component along the subdominant eigenvector, lambda = %1, so the next eigenvalue governs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (the eigenvectors are not complete; the copy&apos;s components were not examined)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertex subdivisions must be square and non-empty, got %1 and %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the free columns must have %1 rows (n_l + n_r), got X %2 and Y %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>free columns X of T^l</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>free columns Y of T^r</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the free columns X of T^l</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the free columns Y of T^r</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 curve&apos;s subdivision operators must both be m x m, got %2 and %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 curve&apos;s vertex dimension must be in 1..%2, got %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 curve needs %2 control points, got %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points of the %1 curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>both curves&apos; control points must have the same dimension</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X must have m_l - n_l columns and Y m_r - n_r</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>junction parameter %1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>T^i has no subdominant eigenvalue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lambda_2 = %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>: |lambda_2| &gt;= 1, T^i does not contract and the junction does not converge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>: both sides have half-tangents along the same eigenvector, from opposite sides: G1 at the junction point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>: both sides have half-tangents, but they are not opposite (a corner or cusp)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the cubic needs 4 and the quadratic 3 control points of one dimension, got %1 and %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 must exceed the other eigenvalues of %2 (largest modulus %3) to be subdominant, and be below 1 for %2 to contract</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refined junction parameter %1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refined junction parameter %1 = %2 is outside its admissible range (%3, %4): %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the refined junction needs 4 cubic, 3 quadratic and 3 handle control points of one dimension, got %1, %2 and %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>handles of the refined junction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the split parameter u is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the split parameter u = %1 must lie strictly between 0 and 1 (002 §4: 0 &lt; u &lt; 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coincide</source>
        <comment>points</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>are collinear</source>
        <comment>points</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>are coplanar</source>
        <comment>points</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the affine map is not invertible (its linear part is singular)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an affine map of R^%1 is fixed by %2 point pairs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>source points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>target points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the source points %1: no unique affine map takes them to the targets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fractal interpolation needs N + 1 &gt;= 3 data points (x, y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>interpolation data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fractal interpolation through %1 points needs %2 vertical scalings d_n, got %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>interpolation abscissae must increase (x_%1 &lt;= x_%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vertical scaling d_%1 = %2 must satisfy |d_n| &lt; 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>002 §5 needs three control points in the plane (3 x 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points Q0, Q1, Q2 are collinear: the map omega of 002 §5 is not invertible</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Bézier curve needs at least 2 control points (degree &gt;= 1), got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points must have 1 to 3 coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 control points %2, so the affine maps of eqs. (9)-(10) are not unique</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no affine map of R^%1 takes the control polygon of this degree-%2 curve to its de Casteljau pieces (mismatch %3): the pieces are not affine images of the curve in its own space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; the maps act on barycentric coordinates R^%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; the maps act on the lifted space R^%1 of 000 §2, drawn through its first %2 coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map 1 has spectral radius %1, map 2 %2; %3 levels shrink every piece to 1/1000 of the curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>. u = %1 is close to %2: map %3 is nearly non-contractive and the pieces are very unequal (random iteration, or u nearer 1/2, converges faster)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>. Map %1 is not a Euclidean contraction (||A||_2 = %2) but is eventually contractive, as 002 §5 allows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a combined IFS needs at least one curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>curve %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the combined IFS of 002 §6 acts on the plane, control points need 2 coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: its maps do not act on the plane (%2), so they cannot be combined with the other curves&apos; maps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a union needs at least one curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>arc &apos;%1&apos; (%2 -&gt; %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the automaton has no states</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>state &apos;%1&apos; has no control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>state &apos;%1&apos;: control points must be 2D or 3D, got %2 coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points of state &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at most 255 arcs are supported (addresses are bytes), got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>arc &apos;%1&apos; connects states %2 -&gt; %3, but the automaton has %4 states</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has a %2 x %3 matrix; it must be %4 x %5 (row convention: rows = dimension of &apos;%6&apos;, columns = dimension of &apos;%7&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>row %1 of %2 sums to %3, not 1: the map does not keep barycentric coordinates summing to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the weight of %1 must be a finite number &gt; 0, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>state &apos;%1&apos; has no outgoing arc: its attractor would be empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the barycentric part needs a non-empty square matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cycle %1 has spectral radius %2 &gt;= 1 on the barycentric directions: repeating it does not contract, so the automaton has no attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a fixed point needs a non-empty square matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the fixed point is not unique: 1 is a repeated eigenvalue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>state %1 does not exist: the automaton has %2 states</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>one start set per state is needed: the automaton has %1 states, got %2 start sets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start set of state &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has %2 coordinates, the state&apos;s space has %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at most 4e9 random-iteration samples, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the affine map&apos;s translation does not match its linear part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a barycentric frame in %1D needs %2 points, got a %3 x %4 matrix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>domain frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>image frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>affine map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the image frame&apos;s points are affinely dependent (collinear in 2D)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map %1 does not act on the same space as map 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map %1 (linear part)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map %1 (translation)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>view %1 does not fit the IFS space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the IFS has %1 maps but %2 probabilities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>probability of map %1 must be a finite number &gt;= 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the map probabilities sum to 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the lifting needs %1 distinct free rows of the control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> and </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the lifted matrix P is nearly singular (reciprocal condition number %1): M_i = P^-1 S_i P lose about %2 of 16 significant digits; control points %3 are almost collinear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the lifted matrix P is nearly singular (reciprocal condition number %1): M_i = P^-1 S_i P lose about %2 of 16 significant digits; control points %3 are almost coplanar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points %1 are collinear, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points %1 are coplanar, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points %1 are affinely dependent, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>matrix S_%1 does not match %2 control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>matrix S_%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start points must have %1 (plane) or %2 (barycentric) coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start points must have %1 (plane) or %2 (lifted) coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a union needs at least one component</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>component %1 has %2 maps, component 1 has %3: a block union needs equally many</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>probabilities must be finite and non-negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the probabilities sum to zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the lattice lists %1 coordinates for %2 control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a map is listed twice among the maps used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map index %1 is out of range: the %2 layout has maps 0 to %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::render</name>
    <message>
        <source>raster size must be between 1x1 and 32768x32768, got %1x%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>supersampling must be 1 to 4 cells per pixel side, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the supersampled raster would hold more than 1.2e9 cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>raster world rectangle is empty or not finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot merge density images of different sizes or modes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>density image does not match its frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a view does not fit the IFS space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there is no IFS to draw</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the IFS has no view to draw it with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the colour table does not cover the address labels</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>awb::schemes</name>
    <message>
        <source>%1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 = %2 &lt; 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 = %2: on the circle %1 = 1, so %3 is an isometry, not a contraction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 = %2 &gt; 1, so %3 expands</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y must be a finite nonzero number (t = 1/2 + i y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = 1/2 + i y with y = %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth must be between 1 and 24, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the subdivision parameter t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies inside both discs: the IFS is hyperbolic (contraction factor %4) and its attractor is a connected curve (Theorem 3.7.2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies outside both discs |t| &lt; 1 and |1 - t| &lt; 1: the IFS is not hyperbolic and has no attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies outside the disc %4: the IFS is not hyperbolic and has no attractor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a Bézier curve needs at least 2 control points (degree &gt;= 1), got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all control points coincide: the curve is a single point and the lifted matrix of 000 §2 is singular</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>depth must be between 0 and 24, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Takagi function needs a finite x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the number of Takagi terms must be &gt;= 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>binary codes longer than 60 digits are not supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a binary code has digits 0 and 1 only (digit %1 is %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takagi image: needs at least 2 control points, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takagi image: control points and y must be finite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takagi image: depth %1 is outside 1..20</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control points must have 2 or 3 coordinates, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 control points are too few: affine combinations in %2D need at least %3 that are not collinear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 control points are too few: affine combinations in %2D need at least %3 that are not coplanar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the control points are all collinear: they must span the plane to write every image point as their affine combination (000 eq. (5))</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the control points are all coplanar: they must span space to write every image point as their affine combination (000 eq. (5))</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the point has %1 coordinates, the control points have %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the IFS has no maps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map f_%1 is not a map of %2D points like the control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map f_%1 (linear part)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>map f_%1 (translation)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Koch curve with control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sierpinski gasket with control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs %2 control points in the plane, got %3 with %4 coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bézier degree must be at least 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline degree must be at least 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a B-spline of degree %1 needs at least %2 control points (%3 knots), got %4 knots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline knot %1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline knots must be nondecreasing (knot %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline knot vector has an empty domain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an end-interpolating B-spline of degree %1 needs at least %2 control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline needs %1 control points, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme %1: the dilation must be at least 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme %1: the mask holds a non-finite weight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme %1: the mask is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme %1: the mask entries of class (%2, %3) mod %4 sum to %5, not 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme %1: local subdivision matrix not closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme %1: the local subdivision matrix has no eigenvalue 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme %1: the limit eigenvector sums to 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>box spline %1: its directions sum to an odd vector, so the mask has no lattice-point centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bicubic B-spline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop (three-direction quartic box spline)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kobbelt √3 (two rounds)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>positive (edge rotated 90° counter-clockwise)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>negative (edge rotated 90° clockwise)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>constant</source>
        <comment>β sign</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Positive normal: the edge vector P_i P_{i+1} rotated 90° counter-clockwise; negative: rotated clockwise. d_i = |P_i P_{i+1}| n_i. In the β signs (-1)^i, (-1)^(k+i), (-1)^(k+1), k is the level of the polygon being subdivided (the first step has k = 0) and i the 0-based index of the edge.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>p = %1: the normal-vector scheme needs p &gt;= 2 rules, one (α_j, β_j) pair each</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>β has %1 values but α has %2: eq. (1) needs one (α_j, β_j) pair per rule j = 0..p-1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>α_%1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>β_%1 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 β signs given for p = %2 rules: give none, one for all rules, or one per rule</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>p = %1, α = %2, β = %3, β signs (%4), normals %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the normal-vector scheme works in the plane: control points need 2 coordinates, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control polygon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a closed control polygon needs at least %1 points, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>an open control polygon needs at least %1 points, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>open control polygons need α_0 = β_0 = 0: rule 0 at the last point (i = p^k n in eq. (1)) would use a point after the end; close the polygon instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the number of subdivision steps cannot be negative, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the subdivision level cannot be negative, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 subdivision steps of a polygon with %2 edges would make %3 points (at most %4); use fewer steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>convergent: every edge shrinks by a factor of at most %1 per step, so ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (longest initial edge) and F^k is a Cauchy sequence (the argument of 001 Theorem 1); non-rectifiable: the polygon length grows by a factor of at least %3 per step (001 Theorem 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>convergent: every edge shrinks by a factor of at most %1 per step, so ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (longest initial edge) and F^k is a Cauchy sequence (the argument of 001 Theorem 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not decided: the one-step edge bound is %1 &gt;= 1, so the argument of 001 Theorem 1 does not apply (see the measured edge lengths per level)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>α_0 and β_0 are not both 0: the new edge across each old vertex joins two old edges and is not the image of one edge, so no IFS of one similarity per new edge exists</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>new edge %1 of the unit edge has length %2 &gt;= 1: no map would contract</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no IFS of %1 similarities (each new edge taken forward or reversed, plain or mirrored: %2 patterns) reproduces the polygons of the first %3 steps; the β sign changes with the level, so the rules repeat only every two steps (an IFS would need p^2 maps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no IFS of %1 similarities (each new edge taken forward or reversed, plain or mirrored: %2 patterns) reproduces the polygons of the first %3 steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no equivalent IFS: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edge %1 of the control polygon is subdivided with rules no similarity copy of the unit edge&apos;s limit reproduces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lévy C curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>binary interpolatory; new point at the apex of a right isosceles triangle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dragon curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheme (2) with β_1 = (-1)^i / 2: the bump alternates sides along the curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sierpiński gasket (arrowhead curve)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>non-stationary and non-uniform, as in the paper: β_1 = β_2 = (-1)^(k+i) √3/4 flips with the level k and the edge i; the polygons tend to the gasket</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Koch curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>quaternary interpolatory; the limit is the classic Koch curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Koch snowflake</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the triangle traversed counter-clockwise with negative normals, so every bump points outwards (NOTES.md)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tigerhead-like curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>α = (0, -1/4, 1/2, 5/4), β = (0, 1/3, 1/2, 1/3): rules 1 and 3 lie outside the edge, so the curve overlaps itself</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Human-like curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>β = (-1)^(k+1) (0, 1/3, 1/2, 1/3): the bumps point down at the first step (k = 0) and flip at every level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Approximating curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>α_0 = -1/2 moves the old points, so the polygon must be closed; the text does not give the quadrilateral of Fig. 3(c): a unit square traversed counter-clockwise is assumed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Crown-like curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>6-ary interpolatory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>7-ary square-wave curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the paper calls it the Minkowski curve; it equals the Minkowski sausage only at level 1 (its middle edge has length 1/2 and is replaced by a half-size copy), so it is a different curve of similarity dimension log_2 3, not 1.5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown normal-vector preset %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs exactly %2 control points, got %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs at least %2 control points, got %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the arity of a scheme must be at least 2, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a scheme of arity %2 needs %2 rules, got %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: rule %2 has no weights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: weight %2 of rule %3 is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the weights of rule %2 sum to %3, not 1 (an affine rule must reproduce constants)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B-spline degree must be between 1 and 15, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>uniform B-spline of degree %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corner cutting needs 0 &lt; a &lt; b &lt; 1, got a = %1, b = %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corner cutting (%1, %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>four-point tension omega is not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>four-point (omega = %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bézier degree must be between 1 and 30, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the de Casteljau split parameter t must lie strictly between 0 and 1, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bézier of degree %1 (de Casteljau at t = %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>end-interpolating B-spline of degree %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: an IFS needs at least two matrices, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: matrix S_1 is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: matrix S_%2 is %3 x %4, expected %5 x %5 like S_1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: matrix S_%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: matrix S_%2, row %3 sums to %4, not 1 (subdivision rows are affine combinations)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the number of subdivision steps cannot be negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>classic subdivision with %1 steps would make %2 points; use fewer steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>user matrices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the square lattice of %1 has no layout &apos;%2&apos; (it has: %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the triangular lattice of %1 has no layout &apos;%2&apos; (it has: %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the mask is not symmetric under the turn of map %2 of the %3 layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the pieces of the %2 layout are not determined by a finite net</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the patch needs %1 control points on its net, got %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lattice point %1 is given twice (points %2 and %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lattice point %1 (point %2) is not on the square net of the patch; missing: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lattice point %1 (point %2) is not on the triangular net of the patch; missing: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the net has %1 lattice points but %2 control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refinement rounds must be from 0 to 12, got %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the mesh was refined by another scheme</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Subdivision curves as attractors of IFS.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project file to open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select the item with this name after opening.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the current item&apos;s figure sheet to this PDF file, then quit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save a picture of the main window to this PNG file once the attractor is drawn, then quit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Window size for --screenshot, WIDTHxHEIGHT.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export a figure of the current item to this file (.png, .svg, .pdf; .tex for the matrices), then quit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resolution of --export-figure in dpi (36..2400).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What --export-figure shows: attractor, spectrum, matrices, analysis or sheet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size of --export-figure in pixels at its resolution, WIDTHxHEIGHT (16..20000).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--export-figure without the grid.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--export-figure without control polygons and start set.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--export-figure framed tightly around the content (the height follows its proportions).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Font of --export-figure&apos;s labels: FAMILY or FAMILY,POINTS.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
