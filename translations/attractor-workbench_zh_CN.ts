<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN" sourcelanguage="en">
<context>
    <name></name>
    <message>
        <source>valence %1, %2, %3</source>
        <translation type="vanished">价 %1，%2，%3</translation>
    </message>
    <message>
        <source>on the boundary</source>
        <translation type="vanished">位于边界</translation>
    </message>
    <message>
        <source>interior</source>
        <translation type="vanished">内部</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the net of the vertex&apos;s piece).</source>
        <translation type="vanished">局部细分矩阵 S：%1 × %1（该顶点所在曲面片的控制网格）。</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the vertex and every point within two faces of it).</source>
        <translation type="vanished">局部细分矩阵 S：%1 × %1（该顶点及其周围两圈面内的所有点）。</translation>
    </message>
    <message>
        <source>λ₁ = 1, λ = %1, μ = %2, λ² = %3</source>
        <translation type="vanished">λ₁ = 1，λ = %1，μ = %2，λ² = %3</translation>
    </message>
    <message>
        <source> (λ in closed form: %1)</source>
        <translation type="vanished">（λ 的闭式值：%1）</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for interior vertices only: a boundary vertex follows the crease rules, whose analysis needs the boundary&apos;s own characteristic map.</source>
        <translation type="vanished">此处仅对内部顶点判定 Reif 判据：边界顶点遵循折痕规则，其分析需要边界自身的特征映射。</translation>
    </message>
    <message>
        <source>spectral condition 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ real</source>
        <translation type="vanished">谱条件 1 &gt; λ₂ = λ₃ &gt; |λ₄|，λ 为实数</translation>
    </message>
    <message>
        <source>characteristic map regular: the Jacobian keeps one sign on all %1 cells (signed areas %2 … %3)</source>
        <translation type="vanished">特征映射正则：雅可比行列式在全部 %1 个单元上保持同号（有向面积 %2 … %3）</translation>
    </message>
    <message>
        <source>characteristic map not regular: signed areas from %1 to %2</source>
        <translation type="vanished">特征映射非正则：有向面积从 %1 到 %2</translation>
    </message>
    <message>
        <source>characteristic map injective: its boundary winds %1 time(s) around the vertex</source>
        <translation type="vanished">特征映射为单射：其边界绕顶点 %1 圈</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): the limit surface is C¹ at the vertex (for generic data).</source>
        <translation type="vanished">判定（Reif 1995）：极限曲面在该顶点处为 C¹（对一般数据）。</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): C¹ is not established at the vertex.</source>
        <translation type="vanished">判定（Reif 1995）：未能确认该顶点处为 C¹。</translation>
    </message>
    <message>
        <source>μ &lt; λ²: the curvature is zero at the vertex (the surface is flat there to second order, for generic data: no convex or saddle shape can be modelled at it)</source>
        <translation type="vanished">μ &lt; λ²：顶点处的曲率为零（对一般数据，曲面在该处二阶平坦：无法在该处构造凸形或鞍形）</translation>
    </message>
    <message>
        <source>μ = λ²: the curvature is bounded at the vertex</source>
        <translation type="vanished">μ = λ²：顶点处的曲率有界</translation>
    </message>
    <message>
        <source>μ &gt; λ²: the curvature is unbounded at the vertex (for generic data)</source>
        <translation type="vanished">μ &gt; λ²：顶点处的曲率无界（对一般数据）</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3), normal (%4, %5, %6).</source>
        <translation type="vanished">极限位置 (%1, %2, %3)，法向量 (%4, %5, %6)。</translation>
    </message>
</context>
<context>
    <name>ExportDialog</name>
    <message>
        <source>Export Figure</source>
        <translation>导出图形</translation>
    </message>
    <message>
        <source>&amp;View:</source>
        <translation>视图(&amp;V)：</translation>
    </message>
    <message>
        <source>The view or figure to export.</source>
        <translation>要导出的视图或图形。</translation>
    </message>
    <message>
        <source>Attractor view</source>
        <translation>吸引子视图</translation>
    </message>
    <message>
        <source>Spectrum plot</source>
        <translation>谱图</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>矩阵</translation>
    </message>
    <message>
        <source>Analysis chart (current tab)</source>
        <translation>分析图表（当前标签页）</translation>
    </message>
    <message>
        <source>Figure sheet</source>
        <translation>图形页</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>文件(&amp;F)：</translation>
    </message>
    <message>
        <source>File to write; its suffix (.png, .svg or .pdf; .tex for the matrices as LaTeX) picks the format.</source>
        <translation>要写入的文件；其后缀（.png、.svg 或 .pdf；.tex 表示以 LaTeX 形式导出矩阵）决定格式。</translation>
    </message>
    <message>
        <source>Choose the file to write.</source>
        <translation>选择要写入的文件。</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <source>The suffix picks the format: .png, .svg or .pdf (the Matrices view also .tex: LaTeX bmatrix).</source>
        <translation>后缀决定格式：.png、.svg 或 .pdf（“矩阵”视图还支持 .tex：LaTeX bmatrix）。</translation>
    </message>
    <message>
        <source>&amp;Width:</source>
        <translation>宽度(&amp;W)：</translation>
    </message>
    <message>
        <source>Width of the figure in pixels (for SVG and PDF: pixel units at the resolution below).</source>
        <translation>图形宽度，单位为像素（对于 SVG 和 PDF：按下方分辨率换算的像素单位）。</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>&amp;Height:</source>
        <translation>高度(&amp;H)：</translation>
    </message>
    <message>
        <source>Height of the figure in pixels (for SVG and PDF: pixel units at the resolution below).</source>
        <translation>图形高度，单位为像素（对于 SVG 和 PDF：按下方分辨率换算的像素单位）。</translation>
    </message>
    <message>
        <source>&amp;Resolution:</source>
        <translation>分辨率(&amp;R)：</translation>
    </message>
    <message>
        <source>Resolution in dots per inch (dpi).</source>
        <translation>分辨率，单位为每英寸点数（dpi）。</translation>
    </message>
    <message>
        <source> dpi</source>
        <translation> dpi</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>显示：</translation>
    </message>
    <message>
        <source>Draw the coordinate grid and its labels (when the view shows them).</source>
        <translation>绘制坐标网格线及其标签（当视图显示它们时）。</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>网格线(&amp;G)</translation>
    </message>
    <message>
        <source>Draw the control polygons, the start set and their points and labels.</source>
        <translation>绘制控制多边形、初始集及其点和标签。</translation>
    </message>
    <message>
        <source>&amp;Control points</source>
        <translation>控制点(&amp;C)</translation>
    </message>
    <message>
        <source>Frame the attractor view&apos;s content tightly: the height follows the content&apos;s proportions (the width is kept).</source>
        <translation>紧贴吸引子视图的内容裁剪边框：高度按内容比例确定（宽度保持不变）。</translation>
    </message>
    <message>
        <source>C&amp;rop to contents</source>
        <translation>裁剪到内容(&amp;R)</translation>
    </message>
    <message>
        <source>F&amp;ont:</source>
        <translation>字体(&amp;O)：</translation>
    </message>
    <message>
        <source>Font of the labels and of the figure sheet&apos;s text.</source>
        <translation>标签和图形页文字所用的字体。</translation>
    </message>
    <message>
        <source>Label size in points as the figure is shown at its resolution (0: as on screen).</source>
        <translation>图形按其分辨率显示时的标签字号，单位为磅（0：与屏幕上相同）。</translation>
    </message>
    <message>
        <source>as on screen</source>
        <translation>与屏幕上相同</translation>
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
        <translation>首选项</translation>
    </message>
    <message>
        <source>Default &amp;depth of new items:</source>
        <translation>新对象的默认深度(&amp;D)：</translation>
    </message>
    <message>
        <source>Deterministic depth given to new items.</source>
        <translation>赋予新对象的确定性迭代深度。</translation>
    </message>
    <message>
        <source>&amp;Maximum drawn depth:</source>
        <translation>最大绘制深度(&amp;M)：</translation>
    </message>
    <message>
        <source>Draw at most this depth, whatever the item asks for.</source>
        <translation>无论对象要求多大深度，最多只绘制到此深度。</translation>
    </message>
    <message>
        <source>no limit</source>
        <translation>无限制</translation>
    </message>
    <message>
        <source>Map &amp;colours:</source>
        <translation>映射颜色(&amp;C)：</translation>
    </message>
    <message>
        <source>Colour of map 1</source>
        <translation>映射 1 的颜色</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Colour of map 2</source>
        <translation>映射 2 的颜色</translation>
    </message>
    <message>
        <source>Colour of map 3</source>
        <translation>映射 3 的颜色</translation>
    </message>
    <message>
        <source>Colour of map 4</source>
        <translation>映射 4 的颜色</translation>
    </message>
    <message>
        <source>Colour of map 5</source>
        <translation>映射 5 的颜色</translation>
    </message>
    <message>
        <source>Colour of map 6</source>
        <translation>映射 6 的颜色</translation>
    </message>
    <message>
        <source>Use the views&apos; default colours for all maps.</source>
        <translation>所有映射均使用视图的默认颜色。</translation>
    </message>
    <message>
        <source>Defaults</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>&amp;Autosave interval:</source>
        <translation>自动保存间隔(&amp;A)：</translation>
    </message>
    <message>
        <source>Time between automatic saves of a recovery copy of the project, in seconds.</source>
        <translation>两次自动保存项目恢复副本之间的时间间隔，单位为秒。</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Dask &amp;scheduler:</source>
        <translation>Dask 调度器(&amp;S)：</translation>
    </message>
    <message>
        <source>The address of a running Dask scheduler (tcp://host:8786) on which the Regularity Atlas computes; empty: a local cluster of this machine&apos;s cores.</source>
        <translation>正则性图谱进行计算所用的、正在运行的 Dask 调度器地址（tcp://host:8786）；留空：由本机各核心组成的本地集群。</translation>
    </message>
    <message>
        <source>a local cluster of this machine</source>
        <translation>本机上的本地集群</translation>
    </message>
    <message>
        <source>&amp;Local workers:</source>
        <translation>本地工作进程(&amp;L)：</translation>
    </message>
    <message>
        <source>Worker processes of the local Dask cluster (the Regularity Atlas without a scheduler address).</source>
        <translation>本地 Dask 集群的工作进程数（未设置调度器地址时的正则性图谱）。</translation>
    </message>
    <message>
        <source>one per core</source>
        <translation>每个核心一个</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>%1, Hölder regularity r in [%2, %3] (width %4)</source>
        <translation>%1，Hölder 正则性 r ∈ [%2, %3]（区间宽度 %4）</translation>
    </message>
    <message>
        <source>%1, Hölder regularity r = %2 (exact)</source>
        <translation>%1，Hölder 正则性 r = %2（精确）</translation>
    </message>
    <message>
        <source>%1, Hölder regularity r = %2 (exact: invariant polytope, certificate)</source>
        <translation>%1，Hölder 正则性 r = %2（精确：不变多面体，证书）</translation>
    </message>
    <message>
        <source>; Sobolev (L²) exponent s₂ = %1</source>
        <translation>；Sobolev（L²）指数 s₂ = %1</translation>
    </message>
</context>
<context>
    <name>awb</name>
    <message>
        <source>the SVG does not parse: %1 (line %2, column %3)</source>
        <translation>SVG 无法解析：%1（第 %2 行，第 %3 列）</translation>
    </message>
    <message>
        <source>%1: cannot read the figure: %2</source>
        <translation>%1：无法读取图形：%2</translation>
    </message>
    <message>
        <source>larger than 512 MB</source>
        <translation>大于 512 MB</translation>
    </message>
    <message>
        <source>neither a PNG nor an SVG</source>
        <translation>既不是 PNG 也不是 SVG</translation>
    </message>
    <message>
        <source>its project is larger than 64 MB</source>
        <translation>其项目大于 64 MB</translation>
    </message>
    <message>
        <source>%1: this %2 holds no Attractor Workbench item (only figures exported by Attractor Workbench carry their parameters)</source>
        <translation>%1：此 %2 不包含 Attractor Workbench 对象（只有由 Attractor Workbench 导出的图形才带有其参数）</translation>
    </message>
</context>
<context>
    <name>awb::AddressPanel</name>
    <message>
        <source>Address 0,1,1 or interval [0.25, 0.5]</source>
        <translation>地址 0,1,1 或区间 [0.25, 0.5]</translation>
    </message>
    <message>
        <source>An address selects the sub-copy f_w(A) = f_w1(f_w2(…(A))): map numbers from 0, the outermost map first. A subdivision curve also takes a parameter interval [t0, t1]. Enter selects, an empty field clears.</source>
        <translation>地址用于选择子副本 f_w(A) = f_w1(f_w2(…(A)))：映射从 0 开始编号，最外层的映射在前。细分曲线也接受参数区间 [t0, t1]。按 Enter 选择，清空输入框则取消选择。</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source>Click the attractor to pick an address; click a symbol of it to select that prefix.</source>
        <translation>单击吸引子以拾取地址；单击地址中的某个符号以选择到该符号为止的前缀。</translation>
    </message>
    <message>
        <source>address %1</source>
        <translation>地址 %1</translation>
    </message>
    <message>
        <source>, t ≈ %1</source>
        <translation>，t ≈ %1</translation>
    </message>
    <message>
        <source>Clicked: %1&lt;br&gt;&lt;small&gt;click a symbol to select the prefix up to it&lt;/small&gt;</source>
        <translation>已单击：%1&lt;br&gt;&lt;small&gt;单击某个符号以选择到该符号为止的前缀&lt;/small&gt;</translation>
    </message>
    <message>
        <source>The item drawn has no addresses to select (only items drawn by one IFS in the plane have).</source>
        <translation>所绘制的对象没有可选择的地址（只有由平面上单个 IFS 绘制的对象才有地址）。</translation>
    </message>
    <message>
        <source>a parameter interval selects on a subdivision curve with a real parameter; this item has none</source>
        <translation>参数区间只能在具有实参数的细分曲线上进行选择；此对象没有实参数</translation>
    </message>
    <message>
        <source>t in %1</source>
        <translation>t ∈ %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;t in %1&lt;/b&gt; (%2)&lt;br&gt;Pieces inside it (addresses up to 8 symbols): %3</source>
        <translation>&lt;b&gt;t ∈ %1&lt;/b&gt;（%2）&lt;br&gt;其中的片段（地址最多 8 个符号）：%3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>&lt;br&gt;The control polygons of the first %1 pieces are drawn.</source>
        <translation>&lt;br&gt;已绘制前 %1 个片段的控制多边形。</translation>
    </message>
    <message>
        <source>w = %1</source>
        <translation>w = %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;w = %1&lt;/b&gt;: the sub-copy f_w(A) = %2(A)</source>
        <translation>&lt;b&gt;w = %1&lt;/b&gt;：子副本 f_w(A) = %2(A)</translation>
    </message>
    <message>
        <source>   t in [%1, %2]</source>
        <translation>   t ∈ [%1, %2]</translation>
    </message>
    <message>
        <source>&lt;br&gt;t in [%1, %2] (%3)</source>
        <translation>&lt;br&gt;t ∈ [%1, %2]（%3）</translation>
    </message>
    <message>
        <source>&lt;br&gt;Control points S_w P = %1 (symbol i is S_(i+1)):&lt;br&gt;%2</source>
        <translation>&lt;br&gt;控制点 S_w P = %1（符号 i 对应 S_(i+1)）：&lt;br&gt;%2</translation>
    </message>
</context>
<context>
    <name>awb::AlgorithmSpec</name>
    <message>
        <source>the depth cannot be negative, got %1</source>
        <translation>深度不能为负数，实际为 %1</translation>
    </message>
    <message>
        <source>depth %1 is absurd: at most %2 is allowed</source>
        <translation>深度 %1 过大：最多允许 %2</translation>
    </message>
    <message>
        <source>the sample count must be between 1 and 2^31, got %1</source>
        <translation>样本数必须介于 1 和 2^31 之间，实际为 %1</translation>
    </message>
    <message>
        <source>the seed must be between 0 and 2^53 - 1, got %1</source>
        <translation>随机种子必须介于 0 和 2^53 - 1 之间，实际为 %1</translation>
    </message>
    <message>
        <source>probability %1 must be a finite number &gt;= 0</source>
        <translation>概率 %1 必须是 &gt;= 0 的有限数</translation>
    </message>
    <message>
        <source>the probabilities sum to 0</source>
        <translation>概率之和为 0</translation>
    </message>
    <message>
        <source>depth %1 with %2 maps makes %3 images of the start set, more than 2^31: at most depth %4 for %2 maps</source>
        <translation>深度 %1 与 %2 个映射产生 %3 个初始集的像，超过 2^31：%2 个映射最多深度 %4</translation>
    </message>
</context>
<context>
    <name>awb::AnalysisCharts</name>
    <message>
        <source>Distance to the exact curve</source>
        <translation>到精确曲线的距离</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>距离</translation>
    </message>
    <message>
        <source>Control polygon length</source>
        <translation>控制多边形长度</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Box counting</source>
        <translation>盒计数</translation>
    </message>
    <message>
        <source>Eigenvalue moduli</source>
        <translation>特征值的模</translation>
    </message>
    <message>
        <source>|λ| per map</source>
        <translation>各映射的 |λ|</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;depth k = %2&lt;br&gt;d&lt;sub&gt;H&lt;/sub&gt; = %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;深度 k = %2&lt;br&gt;d&lt;sub&gt;H&lt;/sub&gt; = %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;step k = %2&lt;br&gt;length = %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;步数 k = %2&lt;br&gt;长度 = %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;log(1/ε) = %2 (ε = %3)&lt;br&gt;log N(ε) = %4 (N = %5)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;log(1/ε) = %2（ε = %3）&lt;br&gt;log N(ε) = %4（N = %5）</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;|λ| = %2</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;|λ| = %2</translation>
    </message>
    <message>
        <source>depth k</source>
        <translation>深度 k</translation>
    </message>
    <message>
        <source>Hausdorff distance</source>
        <translation>Hausdorff 距离</translation>
    </message>
    <message>
        <source>control polygon</source>
        <translation>控制多边形</translation>
    </message>
    <message>
        <source>exact curve</source>
        <translation>精确曲线</translation>
    </message>
    <message>
        <source>subdivision step k</source>
        <translation>细分步数 k</translation>
    </message>
    <message>
        <source>length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Box counting: no fit (%1)</source>
        <translation>盒计数：无法拟合（%1）</translation>
    </message>
    <message>
        <source>not fitted</source>
        <translation>未拟合</translation>
    </message>
    <message>
        <source>fitted levels</source>
        <translation>拟合所用层级</translation>
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
        <translation>映射</translation>
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
        <translation>该对象没有已知的精确曲线</translation>
    </message>
    <message>
        <source>The Hausdorff distance is measured against an exact curve: B-spline, Bézier and complex de Casteljau curves have one.</source>
        <translation>Hausdorff 距离是相对于精确曲线测量的：B 样条、Bézier 曲线和复 de Casteljau 曲线都有精确曲线。</translation>
    </message>
    <message>
        <source>∝ (%1)ᵏ</source>
        <translation>∝ (%1)ᵏ</translation>
    </message>
    <message>
        <source>D = %1 (R² = %2)</source>
        <translation>D = %1（R² = %2）</translation>
    </message>
    <message>
        <source>Box-counting dimension D = %1: the slope of log N(ε) against log(1/ε) over the fitted levels, log N = %1 log(1/ε) + %2, R² = %3</source>
        <translation>盒计数维数 D = %1：在拟合层级上 log N(ε) 对 log(1/ε) 的斜率，log N = %1 log(1/ε) + %2，R² = %3</translation>
    </message>
    <message>
        <source>No fit</source>
        <translation>无拟合</translation>
    </message>
    <message>
        <source>slope %1</source>
        <translation>斜率 %1</translation>
    </message>
</context>
<context>
    <name>awb::Animation</name>
    <message>
        <source>expected a duration in seconds above 0 and at most %1</source>
        <translation>时长应大于 0 秒且不超过 %1 秒</translation>
    </message>
    <message>
        <source>expected between 1 and %1 frames per second</source>
        <translation>每秒帧数应介于 1 和 %1 之间</translation>
    </message>
    <message>
        <source>%1 s at %2 frames per second makes more than %3 frames</source>
        <translation>%1 s、每秒 %2 帧将产生超过 %3 帧</translation>
    </message>
    <message>
        <source>names no parameter</source>
        <translation>未指定任何参数</translation>
    </message>
    <message>
        <source>%1 is driven by an earlier track already</source>
        <translation>%1 已由前面的轨道驱动</translation>
    </message>
    <message>
        <source>needs at least one key</source>
        <translation>至少需要一个关键帧</translation>
    </message>
    <message>
        <source>expected a time between 0 and the duration, %1 s</source>
        <translation>时间应介于 0 和动画时长 %1 s 之间</translation>
    </message>
    <message>
        <source>key times must increase (%1 s follows %2 s)</source>
        <translation>关键帧时间必须递增（%1 s 在 %2 s 之后）</translation>
    </message>
    <message>
        <source>expected %1 numbers, as the first key</source>
        <translation>应为 %1 个数，与第一个关键帧相同</translation>
    </message>
    <message>
        <source>not a finite number</source>
        <translation>不是有限数</translation>
    </message>
    <message>
        <source>a circle turns a point or a complex value, not one number</source>
        <translation>圆周路径只能旋转点或复数值，不能旋转单个数</translation>
    </message>
    <message>
        <source>expected [x, y]</source>
        <translation>应为 [x, y]</translation>
    </message>
    <message>
        <source>expected a number of turns between -1000 and 1000</source>
        <translation>圈数应介于 -1000 和 1000 之间</translation>
    </message>
    <message>
        <source>Probabilities</source>
        <translation>概率</translation>
    </message>
    <message>
        <source>Points %1, point %2</source>
        <translation>点集 %1，第 %2 个点</translation>
    </message>
    <message>
        <source>Control point %1</source>
        <translation>控制点 %1</translation>
    </message>
    <message>
        <source>%1 has no probabilities</source>
        <translation>%1 没有概率</translation>
    </message>
    <message>
        <source>%1 has no control point %2 in point set %3</source>
        <translation>%1 在点集 %3 中没有控制点 %2</translation>
    </message>
    <message>
        <source>%1 is not a number that can be animated</source>
        <translation>%1 不是可以设置动画的数值</translation>
    </message>
    <message>
        <source>%1 has no parameter %2 (now)</source>
        <translation>%1（当前）没有参数 %2</translation>
    </message>
    <message>
        <source>no such control point</source>
        <translation>没有这个控制点</translation>
    </message>
    <message>
        <source>the point was refused</source>
        <translation>该点被拒绝</translation>
    </message>
    <message>
        <source>no such parameter now</source>
        <translation>当前没有这个参数</translation>
    </message>
    <message>
        <source>a complex value needs 2 numbers</source>
        <translation>复数值需要 2 个数</translation>
    </message>
    <message>
        <source>%1 at %2 s: %3</source>
        <translation>%1 在 %2 s 处：%3</translation>
    </message>
    <message>
        <source>the value was refused</source>
        <translation>该值被拒绝</translation>
    </message>
    <message>
        <source>%1 has %2 coordinates, the keys %3</source>
        <translation>%1 有 %2 个坐标，而关键帧有 %3 个</translation>
    </message>
    <message>
        <source>p = (%1)</source>
        <translation>p = (%1)</translation>
    </message>
    <message>
        <source>t = %1 s: %2</source>
        <translation>t = %1 s：%2</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>缺失</translation>
    </message>
    <message>
        <source>expected an array of tracks</source>
        <translation>应为轨道数组</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>应为对象</translation>
    </message>
    <message>
        <source>expected an array of keys</source>
        <translation>应为关键帧数组</translation>
    </message>
    <message>
        <source>expected an object {&quot;time&quot;, &quot;value&quot;}</source>
        <translation>应为对象 {&quot;time&quot;, &quot;value&quot;}</translation>
    </message>
    <message>
        <source>unknown field of a key</source>
        <translation>关键帧的未知字段</translation>
    </message>
    <message>
        <source>unknown field of a track</source>
        <translation>轨道的未知字段</translation>
    </message>
    <message>
        <source>unknown field of an animation</source>
        <translation>动画的未知字段</translation>
    </message>
</context>
<context>
    <name>awb::AnimationPanel</name>
    <message>
        <source>Play / pause the animation (Ctrl+Space)</source>
        <translation>播放/暂停动画（Ctrl+Space）</translation>
    </message>
    <message>
        <source>Stop: the views show the item itself again</source>
        <translation>停止：视图重新显示对象本身</translation>
    </message>
    <message>
        <source>Time: drag to see the frames (the views follow)</source>
        <translation>时间：拖动以查看各帧（视图随之更新）</translation>
    </message>
    <message>
        <source>Time and frame number</source>
        <translation>时间和帧号</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>循环</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Duration of the animation</source>
        <translation>动画时长</translation>
    </message>
    <message>
        <source>Frames per second</source>
        <translation>每秒帧数</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>Parameter / key time (s)</source>
        <translation>参数/关键帧时间 (s)</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Double-click a key&apos;s time or value to edit it</source>
        <translation>双击关键帧的时间或值以进行编辑</translation>
    </message>
    <message>
        <source>The parameter, probabilities or control point to key</source>
        <translation>要设置关键帧的参数、概率或控制点</translation>
    </message>
    <message>
        <source>Set Key</source>
        <translation>设置关键帧</translation>
    </message>
    <message>
        <source>Store the item&apos;s present value of the parameter at the time shown (replaces a key at that time)</source>
        <translation>在所示时间处保存对象该参数的当前值（替换该时间处已有的关键帧）</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Remove the selected key, or the selected track with its keys</source>
        <translation>移除所选关键帧，或所选轨道及其全部关键帧</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>线性</translation>
    </message>
    <message>
        <source>Smooth (ease in and out)</source>
        <translation>平滑（缓入缓出）</translation>
    </message>
    <message>
        <source>Through the keys</source>
        <translation>经过各关键帧</translation>
    </message>
    <message>
        <source>Circle about a centre</source>
        <translation>绕中心做圆周运动</translation>
    </message>
    <message>
        <source>x, y</source>
        <translation>x, y</translation>
    </message>
    <message>
        <source>Interpolation</source>
        <translation>插值</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>路径</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>中心</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>圈数</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>The views show the item itself.</source>
        <translation>视图显示对象本身。</translation>
    </message>
    <message>
        <source>%1 s · %2/%3</source>
        <translation>%1 s · %2/%3</translation>
    </message>
    <message>
        <source>Frame at %1 s: %2</source>
        <translation>%1 s 处的帧：%2</translation>
    </message>
    <message>
        <source>The views show the frame at %1 s (not editable); Stop returns to the item.</source>
        <translation>视图显示 %1 s 处的帧（不可编辑）；按“停止”返回对象本身。</translation>
    </message>
    <message>
        <source>No item is selected.</source>
        <translation>未选择对象。</translation>
    </message>
    <message>
        <source>Select a key or a track to remove.</source>
        <translation>请选择要移除的关键帧或轨道。</translation>
    </message>
    <message>
        <source>inactive: %1 has no such input now</source>
        <translation>未生效：%1 当前没有此输入</translation>
    </message>
    <message>
        <source>circle about (%1), %2 turns</source>
        <translation>绕 (%1) 旋转，%2 圈</translation>
    </message>
    <message>
        <source>The item does not have %1 in its present state (another scheme, fewer points): the track is kept and skipped.</source>
        <translation>对象在当前状态下没有 %1（换了细分格式或点数变少）：该轨道被保留但会被跳过。</translation>
    </message>
    <message>
        <source>Select an item to animate its parameters.</source>
        <translation>选择一个对象以为其参数设置动画。</translation>
    </message>
    <message>
        <source>No keys yet: set a value in Properties, choose it here and press Set Key; then move the slider, change the value and key it again.</source>
        <translation>尚无关键帧：先在“属性”中设置一个值，在此处选中它并按“设置关键帧”；然后移动滑块、更改该值，再次设置关键帧。</translation>
    </message>
    <message>
        <source>%1 has no numeric parameters to animate.</source>
        <translation>%1 没有可设置动画的数值参数。</translation>
    </message>
    <message>
        <source>%1 tracks, %2 frames. Play or drag the slider to preview.</source>
        <translation>%1 条轨道，%2 帧。播放或拖动滑块以预览。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a time in seconds</source>
        <translation>“%1”不是以秒为单位的时间</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: expected %2 numbers</source>
        <translation>“%1”：应为 %2 个数</translation>
    </message>
</context>
<context>
    <name>awb::AtlasPlot</name>
    <message>
        <source>upper bound on r</source>
        <translation>r 的上界</translation>
    </message>
    <message>
        <source>lower bound on r (certified)</source>
        <translation>r 的下界（已证明）</translation>
    </message>
    <message>
        <source>Hölder exponent r</source>
        <translation>Hölder 指数 r</translation>
    </message>
    <message>
        <source>Shaded: certified C&lt;sup&gt;%1&lt;/sup&gt; (lower bound &amp;gt; %1). %2 points.</source>
        <translation>阴影：已证明为 C&lt;sup&gt;%1&lt;/sup&gt;（下界 &amp;gt; %1）。共 %2 个点。</translation>
    </message>
    <message>
        <source>not certified C⁰</source>
        <translation>未证明为 C⁰</translation>
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
        <translation>C³ 或更高</translation>
    </message>
    <message>
        <source>&lt;span style=&quot;color:#c83c14&quot;&gt;□&lt;/span&gt; the bounds cannot tell C&lt;sup&gt;%1&lt;/sup&gt;; white: no member. %2 points.</source>
        <translation>&lt;span style=&quot;color:#c83c14&quot;&gt;□&lt;/span&gt; 上下界无法判定是否为 C&lt;sup&gt;%1&lt;/sup&gt;；白色：无成员。共 %2 个点。</translation>
    </message>
    <message>
        <source>no member here: %1</source>
        <translation>此处无成员：%1</translation>
    </message>
    <message>
        <source>C^∞ (a polynomial piece)</source>
        <translation>C^∞（多项式片段）</translation>
    </message>
    <message>
        <source>Hölder exponent r in [%1, %2]%3</source>
        <translation>Hölder 指数 r 位于 [%1, %2]%3</translation>
    </message>
    <message>
        <source>, exact (invariant polytope)</source>
        <translation>，精确（不变多面体）</translation>
    </message>
    <message>
        <source>certified C^%1</source>
        <translation>已证明为 C^%1</translation>
    </message>
    <message>
        <source>C^%1 as asked: yes</source>
        <translation>所要求的 C^%1：是</translation>
    </message>
    <message>
        <source>C^%1 as asked: certified no</source>
        <translation>所要求的 C^%1：已证明不是</translation>
    </message>
    <message>
        <source>C^%1 as asked: the bounds cannot tell</source>
        <translation>所要求的 C^%1：上下界无法判定</translation>
    </message>
    <message>
        <source>Sobolev exponent s₂ = %1</source>
        <translation>Sobolev 指数 s₂ = %1</translation>
    </message>
    <message>
        <source>stopped by the safety clock: may differ on another machine</source>
        <translation>被安全计时器中止：在其他机器上结果可能不同</translation>
    </message>
    <message>
        <source>Click to add an item with these parameters.</source>
        <translation>单击以添加具有这些参数的项。</translation>
    </message>
</context>
<context>
    <name>awb::AttractorItem</name>
    <message>
        <source>Change start set of %1</source>
        <translation>更改 %1 的初始集</translation>
    </message>
    <message>
        <source>Change algorithm of %1</source>
        <translation>更改 %1 的算法</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n control points of %1</source>
        <translation>
            <numerusform>移除 %1 的 %n 个控制点</numerusform>
        </translation>
    </message>
    <message>
        <source>map %1 is not finite: the control points&apos; coordinates overflow in the lifted map P⁻¹ S_i P (the largest is %2)</source>
        <translation>映射 %1 不是有限的：控制点坐标在提升映射 P⁻¹ S_i P 中溢出（最大值为 %2）</translation>
    </message>
    <message>
        <source>the start set is not finite in the IFS space: the lifting overflows (the largest control point coordinate is %1)</source>
        <translation>初始集在 IFS 空间中不是有限的：提升时溢出（最大的控制点坐标为 %1）</translation>
    </message>
    <message>
        <source>lifted start points need an invertible lifting: %1</source>
        <translation>提升后的初始点需要可逆的提升：%1</translation>
    </message>
    <message>
        <source>a lifted start point of this item has %1 coordinates (x, y and the %2 extra coordinates of the lifting, the homogeneous 1 implied); point %3 has %4</source>
        <translation>此对象提升后的初始点有 %1 个坐标（x、y 以及提升的 %2 个附加坐标，齐次坐标 1 隐含）；点 %3 有 %4 个</translation>
    </message>
    <message>
        <source>%1 points; an item takes at most %2 (its subdivision matrices would be %1 x %1)</source>
        <translation>%1 个点；一个对象最多接受 %2 个（其细分矩阵将为 %1 × %1）</translation>
    </message>
    <message>
        <source>point set %1 has %2 points; an item takes at most %3 per set</source>
        <translation>点集 %1 有 %2 个点；一个对象每个点集最多接受 %3 个点</translation>
    </message>
    <message>
        <source>the start set &quot;vertex-limits&quot; (the limit positions of a mesh&apos;s vertices) is for mesh items only; this item: %1</source>
        <translation>初始集 &quot;vertex-limits&quot;（网格顶点的极限位置）仅适用于网格对象；此对象：%1</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>点</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>线段</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation>三角</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>多边形</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>点集</translation>
    </message>
    <message>
        <source>Lifted points</source>
        <translation>提升点</translation>
    </message>
    <message>
        <source>Vertex limits</source>
        <translation>顶点极限位置</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Start set X0</source>
        <translation>初始集 X0</translation>
    </message>
    <message>
        <source>The set X0 deterministic iteration starts from; drag its vertices in the attractor view. Lifted points are points of the lifted space of 000 §2; vertex limits, a mesh&apos;s vertices&apos; limit positions.</source>
        <translation type="vanished">确定性迭代的初始集 X0；在吸引子视图中拖动其顶点即可修改。提升点是 000 §2 中提升空间的点；顶点极限位置是网格各顶点的极限位置。</translation>
    </message>
    <message>
        <source>The item has no control points.</source>
        <translation>该对象没有控制点。</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>顶点</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number.</source>
        <translation>“%1”不是数。</translation>
    </message>
    <message>
        <source>Lifted</source>
        <translation>提升点</translation>
    </message>
    <message>
        <source>Points of the lifted space of 000 §2: x, y, then the extra coordinates of the lifting, the homogeneous 1 implied. Commas between coordinates, &apos;;&apos; between points.</source>
        <translation>000 §2 提升空间中的点：先是 x、y，然后是提升的附加坐标，齐次坐标 1 隐含。坐标之间用逗号分隔，点之间用“;”分隔。</translation>
    </message>
    <message>
        <source>Deterministic</source>
        <translation>确定性</translation>
    </message>
    <message>
        <source>Random (chaos game)</source>
        <translation>随机（混沌游戏）</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>模式</translation>
    </message>
    <message>
        <source>Algorithm</source>
        <translation>算法</translation>
    </message>
    <message>
        <source>Deterministic iteration draws F^k(X0) at the depth k; random iteration plays the chaos game with the samples</source>
        <translation>确定性迭代绘制深度 k 处的 F^k(X0)；随机迭代按样本数进行混沌游戏</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>深度</translation>
    </message>
    <message>
        <source>The level k of F^k(X0): N^k images of the start set, at most 2^31</source>
        <translation>F^k(X0) 的层级 k：初始集的 N^k 个像，最多 2^31 个</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>样本数</translation>
    </message>
    <message>
        <source>Points of the chaos game</source>
        <translation>混沌游戏的点数</translation>
    </message>
    <message>
        <source>Probabilities</source>
        <translation>概率</translation>
    </message>
    <message>
        <source>One weight per map for the chaos game; none: uniform</source>
        <translation>混沌游戏中每个映射一个权重；不设置：均匀</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>随机种子</translation>
    </message>
    <message>
        <source>The chaos game&apos;s random stream: the same seed, the same picture</source>
        <translation>混沌游戏的随机数序列：种子相同，图像就相同</translation>
    </message>
    <message>
        <source>%1 has no point set %2</source>
        <translation>%1 没有点集 %2</translation>
    </message>
    <message>
        <source>%1: its scheme fixes the number of points at %2, got %3</source>
        <translation>%1：其细分格式将点数固定为 %2，实际为 %3</translation>
    </message>
    <message>
        <source>%1: %2 points is more than the %3 a point set may have</source>
        <translation>%1：%2 个点超过了一个点集最多可有的 %3 个点</translation>
    </message>
    <message>
        <source>every point must have finite coordinates</source>
        <translation>每个点的坐标都必须是有限数</translation>
    </message>
    <message>
        <source>Set the points of %1</source>
        <translation>设置 %1 的点</translation>
    </message>
    <message>
        <source>the points of %1 were refused</source>
        <translation>%1 的点被拒绝</translation>
    </message>
    <message>
        <source>the start set &quot;net&quot; (control points of the net by index) is for items whose IFS is built from one control net (curves, surfaces, fractals with control points); this item: %1</source>
        <translation>初始集 “net”（按索引选取的控制网格点）只适用于由单个控制网格构造 IFS 的对象（曲线、曲面、带控制点的分形）；此对象：%1</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2; this item has %3 control points (indices 0 to %4)</source>
        <translation>初始集的第 %1 个网格点索引为 %2；此对象有 %3 个控制点（索引 0 到 %4）</translation>
    </message>
    <message>
        <source>Net points</source>
        <translation>网格点</translation>
    </message>
    <message>
        <source>The set X0 deterministic iteration starts from; drag its vertices in the attractor view. Lifted points are points of the lifted space of 000 §2; vertex limits, a mesh&apos;s vertices&apos; limit positions; net points, control points by index, which the set follows when they move.</source>
        <translation>确定性迭代的初始集 X0；在吸引子视图中拖动其顶点即可修改。提升点是 000 §2 中提升空间的点；顶点极限位置是网格各顶点的极限位置；网格点是按索引选取的控制点，控制点移动时初始集随之移动。</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a net point index (an integer from 0).</source>
        <translation type="vanished">“%1”不是网格点索引（从 0 开始的整数）。</translation>
    </message>
    <message>
        <source>Control points by index, counted from 0 (commas between them): the start set is their point, segment or polygon in the lifted space, and it follows them when they move.</source>
        <translation>按索引选取的控制点，从 0 开始计数（以逗号分隔）：初始集是它们在提升空间中构成的点、线段或多边形，并随它们移动。</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2; the net has %3 points</source>
        <translation>初始集的第 %1 个网格点索引为 %2；网格只有 %3 个点</translation>
    </message>
    <message>
        <source>this item has no control net to start from</source>
        <translation>此对象没有可作为起点的控制网格</translation>
    </message>
</context>
<context>
    <name>awb::AttractorRenderer</name>
    <message>
        <source>Cannot draw the attractor: %1</source>
        <translation>无法绘制吸引子：%1</translation>
    </message>
</context>
<context>
    <name>awb::AttractorView</name>
    <message>
        <source>Rendering… %1 %</source>
        <translation>正在渲染… %1 %</translation>
    </message>
    <message>
        <source>Rendering cancelled at %1 % — press F5 to render again</source>
        <translation>渲染已在 %1 % 处取消——按 F5 重新渲染</translation>
    </message>
    <message>
        <source>F^%1(X₀) has too many images to draw as vectors</source>
        <translation>F^%1(X₀) 的像太多，无法以矢量形式绘制</translation>
    </message>
    <message>
        <source>there is no attractor to count</source>
        <translation>没有可计数的吸引子</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonAnalysis</name>
    <message>
        <source>every long path contracts</source>
        <translation>每条长路径都是压缩的</translation>
    </message>
    <message>
        <source>some path does not contract</source>
        <translation>存在不压缩的路径</translation>
    </message>
    <message>
        <source>not decided</source>
        <translation>未判定</translation>
    </message>
    <message>
        <source>constrained JSR ρ = %1 exactly (invariant polytope, extremal cycle %2): %3</source>
        <translation>受约束的联合谱半径 ρ = %1（精确值；不变多面体，极值回路 %2）：%3</translation>
    </message>
    <message>
        <source>constrained JSR ρ in [%1, %2]: %3</source>
        <translation>受约束的联合谱半径 ρ 位于 [%1, %2]：%3</translation>
    </message>
    <message>
        <source>Lyapunov exponent of random iteration %1 (%2)</source>
        <translation>随机迭代的李雅普诺夫指数 %1（%2）</translation>
    </message>
    <message>
        <source>contracts on average</source>
        <translation>平均而言是压缩的</translation>
    </message>
    <message>
        <source>does not contract on average</source>
        <translation>平均而言不是压缩的</translation>
    </message>
    <message>
        <source>cycle %1: ρ = %2 (%3 per arc); eigenvalues %4</source>
        <translation>回路 %1：ρ = %2（每条弧 %3）；特征值 %4</translation>
    </message>
    <message>
        <source>… and %1 more cycles</source>
        <translation>…以及另外 %1 个回路</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonGraph</name>
    <message>
        <source>Automaton graph</source>
        <translation>自动机图</translation>
    </message>
    <message>
        <source>No states</source>
        <translation>无状态</translation>
    </message>
    <message>
        <source>%1 pts</source>
        <translation>%1 个点</translation>
    </message>
    <message>
        <source>State %1: %2 control points%3</source>
        <translation>状态 %1：%2 个控制点%3</translation>
    </message>
    <message>
        <source>, drawn</source>
        <translation>，已绘制</translation>
    </message>
    <message>
        <source>Arc %1: %2 → %3 (maps the space of %3 into %2)</source>
        <translation>弧 %1：%2 → %3（将 %3 的空间映射到 %2 的空间）</translation>
    </message>
</context>
<context>
    <name>awb::AutomatonPanel</name>
    <message>
        <source>Select a controlled IFS item to see and edit its automaton (Items &gt; Add &gt; Controlled IFS, or the example 003 Fig. 5).</source>
        <translation type="vanished">选择一个受控IFS项即可查看并编辑其自动机（项 &gt; 添加 &gt; 受控IFS，或示例 003 Fig. 5）。</translation>
    </message>
    <message>
        <source>Drawn:</source>
        <translation>绘制：</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn, or the union of all</source>
        <translation>要绘制其吸引子的状态，或所有状态的并</translation>
    </message>
    <message>
        <source>Add State</source>
        <translation>添加状态</translation>
    </message>
    <message>
        <source> points</source>
        <translation> 个点</translation>
    </message>
    <message>
        <source>The new state&apos;s number of control points: the dimension of its barycentric space (3: a frame triangle)</source>
        <translation>新状态的控制点个数：其重心空间的维数（3：框架三角形）</translation>
    </message>
    <message>
        <source>Remove State</source>
        <translation>删除状态</translation>
    </message>
    <message>
        <source>Add Arc</source>
        <translation>添加弧</translation>
    </message>
    <message>
        <source>A new arc leaving the selected state (into itself; pick its target below)</source>
        <translation>从所选状态出发的新弧（指向其自身；请在下方选择其目标）</translation>
    </message>
    <message>
        <source>Remove Arc</source>
        <translation>删除弧</translation>
    </message>
    <message>
        <source>Click a state or an arc to edit it.</source>
        <translation>单击状态或弧即可对其进行编辑。</translation>
    </message>
    <message>
        <source>State name</source>
        <translation>状态名称</translation>
    </message>
    <message>
        <source>Arc name</source>
        <translation>弧名称</translation>
    </message>
    <message>
        <source>From → to</source>
        <translation>从 → 到</translation>
    </message>
    <message>
        <source>The arc&apos;s relative probability among the arcs leaving its state (random iteration)</source>
        <translation>该弧在从其状态出发的各弧中的相对概率（随机迭代）</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>权重</translation>
    </message>
    <message>
        <source>Matrix S (rows sum to 1)</source>
        <translation>矩阵 S（各行之和为 1）</translation>
    </message>
    <message>
        <source>Plane affine map</source>
        <translation>平面仿射映射</translation>
    </message>
    <message>
        <source>Piece of a curve scheme</source>
        <translation>曲线细分格式的片段</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>映射</translation>
    </message>
    <message>
        <source>S: a row per control point of the target state, a column per control point of the source; numbers like 1/3 are read exactly</source>
        <translation>S：目标状态的每个控制点对应一行，源状态的每个控制点对应一列；1/3 这样的数按精确值读取</translation>
    </message>
    <message>
        <source>Apply Matrix</source>
        <translation>应用矩阵</translation>
    </message>
    <message>
        <source>Apply Affine Map</source>
        <translation>应用仿射映射</translation>
    </message>
    <message>
        <source>x ↦ x A + b, taking the target state&apos;s frame triangle into the plane of the source&apos;s; kept as its matrix</source>
        <translation>x ↦ x A + b，将目标状态的框架三角形映射到源状态框架三角形所在的平面；以其矩阵形式保存</translation>
    </message>
    <message>
        <source>Bézier (de Casteljau at 1/2)</source>
        <translation>Bézier（在 1/2 处的 de Casteljau 算法）</translation>
    </message>
    <message>
        <source>Uniform B-spline</source>
        <translation>均匀 B 样条</translation>
    </message>
    <message>
        <source>End-interpolating B-spline</source>
        <translation>端点插值 B 样条</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Four-point</source>
        <translation>四点格式</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>细分格式</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>次数</translation>
    </message>
    <message>
        <source>Piece S_i, i =</source>
        <translation>片段 S_i, i =</translation>
    </message>
    <message>
        <source>Apply Scheme Piece</source>
        <translation>应用细分格式片段</translation>
    </message>
    <message>
        <source>The analysis of a controlled IFS item: its constrained joint spectral radius, its cycles&apos; spectra and the Lyapunov exponent of random iteration.</source>
        <translation>受控IFS项的分析：其受约束的联合谱半径、各回路的谱以及随机迭代的李雅普诺夫指数。</translation>
    </message>
    <message>
        <source>All states</source>
        <translation>所有状态</translation>
    </message>
    <message>
        <source>Analysing the automaton…</source>
        <translation>正在分析自动机…</translation>
    </message>
    <message>
        <source>Automaton of %1</source>
        <translation>%1 的自动机</translation>
    </message>
    <message>
        <source>%1 control points (its barycentric space), %2 arcs leave it, %3 arrive. Drag its control points in the attractor view.</source>
        <translation>%1 个控制点（其重心空间），%2 条弧从它出发，%3 条弧到达它。可在吸引子视图中拖动其控制点。</translation>
    </message>
    <message>
        <source>S is %1 × %2: a row per point of %3, a column per point of %4. It maps the space of %3 into that of %4.</source>
        <translation>S 为 %1 × %2 矩阵：%3 的每个点对应一行，%4 的每个点对应一列。它将 %3 的空间映射到 %4 的空间。</translation>
    </message>
    <message>
        <source>no controlled IFS item is selected</source>
        <translation>未选中任何受控IFS项</translation>
    </message>
    <message>
        <source>row %1, column %2 of the matrix is not a number: %3</source>
        <translation>矩阵第 %1 行第 %2 列不是数字：%3</translation>
    </message>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 不是数字</translation>
    </message>
    <message>
        <source>Select a controlled IFS item to see and edit its automaton (Item &gt; Add &gt; Controlled IFS, or the example 003 Fig. 5).</source>
        <translation>选择一个受控 IFS 项即可查看并编辑其自动机（对象 &gt; 添加 &gt; 受控 IFS，或示例 003 Fig. 5）。</translation>
    </message>
</context>
<context>
    <name>awb::BcifsJunctionItem</name>
    <message>
        <source>Junction</source>
        <translation>拼接</translation>
    </message>
    <message>
        <source>Change junction of %1</source>
        <translation>更改 %1 的拼接</translation>
    </message>
    <message>
        <source>e = %1, p = %2 (column sums). %3</source>
        <translation>e = %1，p = %2（列和）。%3</translation>
    </message>
    <message>
        <source>a junction is drawn by an automaton, not by one lifted IFS</source>
        <translation>拼接由自动机绘制，而不是由单个提升 IFS 绘制</translation>
    </message>
    <message>
        <source>Cubic–quadratic (003 §4.1)</source>
        <translation>三次–二次（003 §4.1）</translation>
    </message>
    <message>
        <source>Refined, with handles (003 §5)</source>
        <translation>细化，带控制柄（003 §5）</translation>
    </message>
    <message>
        <source>Last column (a, b, c, d, e) of T^l; e = 1 − a − b − c − d (003 §4.1)</source>
        <translation>T^l 的最后一列 (a, b, c, d, e)；e = 1 − a − b − c − d（003 §4.1）</translation>
    </message>
    <message>
        <source>First column (k, l, m, n, p) of T^r; p = 1 − k − l − m − n (003 §4.1)</source>
        <translation>T^r 的第一列 (k, l, m, n, p)；p = 1 − k − l − m − n（003 §4.1）</translation>
    </message>
    <message>
        <source>Left eigenvalue j</source>
        <translation>左特征值 j</translation>
    </message>
    <message>
        <source>Tangent eigenvalue of T^il (003 §5)</source>
        <translation>T^il 的切向特征值（003 §5）</translation>
    </message>
    <message>
        <source>Right eigenvalue r</source>
        <translation>右特征值 r</translation>
    </message>
    <message>
        <source>Tangent eigenvalue of T^ir (003 §5)</source>
        <translation>T^ir 的切向特征值（003 §5）</translation>
    </message>
    <message>
        <source>BCIFS junction curve</source>
        <translation>BCIFS 拼接曲线</translation>
    </message>
    <message>
        <source>Left cubic</source>
        <translation>左侧三次曲线</translation>
    </message>
    <message>
        <source>Right quadratic</source>
        <translation>右侧二次曲线</translation>
    </message>
    <message>
        <source>Handles</source>
        <translation>控制柄</translation>
    </message>
</context>
<context>
    <name>awb::BezierUnionItem</name>
    <message>
        <source>Bézier union</source>
        <translation>Bézier 并集</translation>
    </message>
    <message>
        <source>%1 split parameters for %2 curves</source>
        <translation type="vanished">%2 条曲线却有 %1 个分割参数</translation>
    </message>
    <message>
        <source>Change Bézier union %1</source>
        <translation>更改 Bézier 并集 %1</translation>
    </message>
    <message>
        <source>curve %1: %2</source>
        <translation>曲线 %1：%2</translation>
    </message>
    <message>
        <source>curves drawn in the lifted space of 000 §2: %1</source>
        <translation>在 000 §2 的提升空间中绘制的曲线：%1</translation>
    </message>
    <message>
        <source>every composition of %1 maps contracts (factor %2): the dusty fractal of 002 §6 is the unique attractor</source>
        <translation>%1 个映射的每个复合都是压缩的（压缩因子 %2）：002 §6 中的尘状分形是唯一的吸引子</translation>
    </message>
    <message>
        <source>no contraction was proven (best bound %1 at length %2): the picture may not be an attractor</source>
        <translation>未能证明压缩性（长度 %2 处的最佳界为 %1）：图形可能不是吸引子</translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="vanished">缺失</translation>
    </message>
    <message>
        <source>expected a non-empty array of curves {&quot;control_points&quot;: [...], &quot;u&quot;: number}</source>
        <translation>应为由曲线 {&quot;control_points&quot;: [...], &quot;u&quot;: number} 组成的非空数组</translation>
    </message>
    <message>
        <source>expected an object with &quot;control_points&quot; and &quot;u&quot;</source>
        <translation>应为包含 &quot;control_points&quot; 和 &quot;u&quot; 的对象</translation>
    </message>
    <message>
        <source>Union</source>
        <translation>并集</translation>
    </message>
    <message>
        <source>Exact union (block IFS, 000 §2.2)</source>
        <translation>精确并集（块 IFS，000 §2.2）</translation>
    </message>
    <message>
        <source>All maps together (dusty fractal, 002 §6)</source>
        <translation>所有映射合在一起（尘状分形，002 §6）</translation>
    </message>
    <message>
        <source>Split parameter u</source>
        <translation>分割参数 u</translation>
    </message>
    <message>
        <source>Curve %1</source>
        <translation>曲线 %1</translation>
    </message>
    <message>
        <source>de Casteljau split at u, 0 &lt; u &lt; 1 (002 eqs. (9)-(10)); the curve is the same for every u, the IFS is not</source>
        <translation>在 u 处做 de Casteljau 分割，0 &lt; u &lt; 1（002 eqs. (9)-(10)）；对每个 u 曲线都相同，但 IFS 不同</translation>
    </message>
    <message>
        <source>Union of Bézier curves</source>
        <translation>Bézier 曲线的并集</translation>
    </message>
    <message>
        <source>Curves</source>
        <translation>曲线</translation>
    </message>
    <message>
        <source>Each curve&apos;s control points and split parameter u</source>
        <translation>每条曲线的控制点和分割参数 u</translation>
    </message>
</context>
<context>
    <name>awb::BezierUnionSpec</name>
    <message>
        <source>a union needs at least one curve</source>
        <translation>并集至少需要一条曲线</translation>
    </message>
    <message>
        <source>the split parameter u = %1 must satisfy 0 &lt; u &lt; 1 (002 §3)</source>
        <translation>分割参数 u = %1 必须满足 0 &lt; u &lt; 1（002 §3）</translation>
    </message>
    <message>
        <source>%1 split parameters for %2 curves</source>
        <translation>%2 条曲线却有 %1 个分割参数</translation>
    </message>
</context>
<context>
    <name>awb::CharacteristicMapView</name>
    <message>
        <source>The characteristic map: the n faces around the vertex under the two eigenvectors of the subdominant eigenvalue. Cells where the Jacobian changes sign are red.</source>
        <translation>特征映射：顶点周围的 n 个面在次占优特征值的两个特征向量下的像。雅可比行列式变号的单元显示为红色。</translation>
    </message>
    <message>
        <source>Click an extraordinary vertex in the 3D view to see its characteristic map.</source>
        <translation>在 3D 视图中单击一个奇异顶点以查看其特征映射。</translation>
    </message>
    <message>
        <source>n = %1: regular, %2</source>
        <translation>n = %1：正则，%2</translation>
    </message>
    <message>
        <source>injective</source>
        <translation>单射</translation>
    </message>
    <message>
        <source>not injective</source>
        <translation>非单射</translation>
    </message>
    <message>
        <source>n = %1: the Jacobian changes sign in %2 cells</source>
        <translation>n = %1：雅可比行列式在 %2 个单元中变号</translation>
    </message>
</context>
<context>
    <name>awb::CheckedSpinBox</name>
    <message>
        <source>“%1” is not a whole number.</source>
        <translation>“%1”不是整数。</translation>
    </message>
    <message>
        <source>%1 is outside %2 … %3.</source>
        <translation>%1 超出 %2 … %3。</translation>
    </message>
</context>
<context>
    <name>awb::CifsItem</name>
    <message>
        <source>Fern of gaskets</source>
        <translation>垫片蕨</translation>
    </message>
    <message>
        <source>Change automaton of %1</source>
        <translation>更改 %1 的自动机</translation>
    </message>
    <message>
        <source>the frame needs exactly 3 points, got %1</source>
        <translation type="vanished">框架恰好需要 3 个点，实际为 %1 个</translation>
    </message>
    <message>
        <source>a controlled IFS has no single lifted IFS</source>
        <translation>受控 IFS 没有单个提升 IFS</translation>
    </message>
    <message>
        <source>Arc T%1 of the fern leads into the Sierpiński state (003 §2.2, Fig. 4).</source>
        <translation type="vanished">蕨的弧 T%1 通向 Sierpiński 状态（003 §2.2，Fig. 4）。</translation>
    </message>
    <message>
        <source>Automaton</source>
        <translation>自动机</translation>
    </message>
    <message>
        <source>Redirected arc</source>
        <translation type="vanished">重定向的弧</translation>
    </message>
    <message>
        <source>The fern map (0 stem, 1 main frond, 2 left, 3 right leaflet) whose arc leads into the Sierpiński state (003 Fig. 4)</source>
        <translation type="vanished">其弧通向 Sierpiński 状态的蕨映射（0 茎，1 主叶，2 左小叶，3 右小叶）（003 Fig. 4）</translation>
    </message>
    <message>
        <source>Drawn state</source>
        <translation>绘制的状态</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn</source>
        <translation type="vanished">绘制其吸引子的状态</translation>
    </message>
    <message>
        <source>Controlled IFS</source>
        <translation>受控 IFS</translation>
    </message>
    <message>
        <source>Fern of gaskets (003 Fig. 4)</source>
        <translation type="vanished">垫片蕨（003 Fig. 4）</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation type="vanished">框架</translation>
    </message>
    <message>
        <source>a controlled IFS draws its arcs by their own weights (&quot;arcs&quot;): leave the algorithm&apos;s probabilities empty</source>
        <translation>受控IFS按各弧自身的权重（&quot;arcs&quot;）抽取弧：请将算法的概率留空</translation>
    </message>
    <message>
        <source>arcs between states of different dimensions have rectangular matrices: see the automaton&apos;s analysis</source>
        <translation>连接不同维数状态的弧具有矩形矩阵：请参见自动机的分析</translation>
    </message>
    <message>
        <source>The union of the attractors of the automaton&apos;s %1 states (003 §2.2).</source>
        <translation>自动机 %1 个状态的吸引子之并（003 §2.2）。</translation>
    </message>
    <message>
        <source>The attractor of state %1 of the automaton (003 §2.2).</source>
        <translation>自动机状态 %1 的吸引子（003 §2.2）。</translation>
    </message>
    <message>
        <source>States</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Each state&apos;s name and control points (its barycentric space)</source>
        <translation>每个状态的名称和控制点（其重心空间）</translation>
    </message>
    <message>
        <source>Arcs</source>
        <translation>弧</translation>
    </message>
    <message>
        <source>Each arc&apos;s states and matrix S (a row per point of the state it leads to, rows summing to 1) and weight</source>
        <translation>每条弧的状态、矩阵 S（其所指向状态的每个点对应一行，各行之和为 1）以及权重</translation>
    </message>
    <message>
        <source>The state whose attractor is drawn, or the union of all</source>
        <translation>要绘制其吸引子的状态，或所有状态的并</translation>
    </message>
</context>
<context>
    <name>awb::CifsSpec</name>
    <message>
        <source>the redirected fern arc must be 0 … 3 (T0 … T3), got %1</source>
        <translation type="vanished">重定向的蕨弧必须为 0 … 3（T0 … T3），实际为 %1</translation>
    </message>
    <message>
        <source>no state &quot;%1&quot;; the states are &quot;%2&quot;</source>
        <translation type="vanished">没有状态 &quot;%1&quot;；现有状态为 &quot;%2&quot;</translation>
    </message>
    <message>
        <source>expected a matrix: a non-empty array of rows</source>
        <translation>应为矩阵：由行组成的非空数组</translation>
    </message>
    <message>
        <source>a %1 x %2 matrix: a state has at most %3 points</source>
        <translation>%1 x %2 矩阵：一个状态最多有 %3 个点</translation>
    </message>
    <message>
        <source>expected a row of %1 numbers, like row 1</source>
        <translation>应为包含 %1 个数的行，与第 1 行一样</translation>
    </message>
    <message>
        <source>no state %1; the states are %2</source>
        <translation>没有状态 %1；现有状态为 %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>expected a state&apos;s name</source>
        <translation>应为状态名称</translation>
    </message>
    <message>
        <source>missing: give the arc&apos;s map as &quot;matrix&quot;, &quot;columns&quot;, &quot;affine&quot; or &quot;scheme&quot;</source>
        <translation>缺失：请以 &quot;matrix&quot;、&quot;columns&quot;、&quot;affine&quot; 或 &quot;scheme&quot; 给出弧的映射</translation>
    </message>
    <message>
        <source>give the arc&apos;s map one way, not as %1</source>
        <translation>请只用一种方式给出弧的映射，不要同时使用 %1</translation>
    </message>
    <message>
        <source> and </source>
        <translation> 和 </translation>
    </message>
    <message>
        <source>a plane affine map needs both states to have 3 control points (a frame triangle): %1 has %2, %3 has %4</source>
        <translation>平面仿射映射要求两个状态都有 3 个控制点（框架三角形）：%1 有 %2 个，%3 有 %4 个</translation>
    </message>
    <message>
        <source>expected {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</source>
        <translation>应为 {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</translation>
    </message>
    <message>
        <source>A must be 2 x 2 and b two numbers</source>
        <translation>A 必须为 2 x 2，b 必须为两个数</translation>
    </message>
    <message>
        <source>expected a curve scheme, as a curve item&apos;s &quot;scheme&quot;</source>
        <translation>应为曲线细分格式，与曲线项的 &quot;scheme&quot; 相同</translation>
    </message>
    <message>
        <source>a scheme&apos;s matrix is square: %1 has %2 points, %3 has %4</source>
        <translation>细分格式的矩阵是方阵：%1 有 %2 个点，%3 有 %4 个</translation>
    </message>
    <message>
        <source>an automaton needs at least one state</source>
        <translation>自动机至少需要一个状态</translation>
    </message>
    <message>
        <source>%1 states: at most %2</source>
        <translation>%1 个状态：最多 %2 个</translation>
    </message>
    <message>
        <source>a state needs a name</source>
        <translation>状态必须有名称</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names all states; call the state otherwise</source>
        <translation>&quot;%1&quot; 表示所有状态；请为该状态另取名称</translation>
    </message>
    <message>
        <source>two states are called %1</source>
        <translation>有两个状态都名为 %1</translation>
    </message>
    <message>
        <source>a state needs 1 to %1 control points, got %2</source>
        <translation>状态需要 1 至 %1 个控制点，实际为 %2 个</translation>
    </message>
    <message>
        <source>state %1 has a control point that is not finite</source>
        <translation>状态 %1 含有非有限的控制点</translation>
    </message>
    <message>
        <source>%1 arcs: at most %2 (addresses are bytes)</source>
        <translation>%1 条弧：最多 %2 条（地址为字节）</translation>
    </message>
    <message>
        <source>an arc needs a name</source>
        <translation>弧必须有名称</translation>
    </message>
    <message>
        <source>two arcs are called %1</source>
        <translation>有两条弧都名为 %1</translation>
    </message>
    <message>
        <source>arc %1 leads between states that do not exist</source>
        <translation>弧 %1 连接的状态不存在</translation>
    </message>
    <message>
        <source>arc %1 has a %2 x %3 matrix; from %4 (%5 points) to %6 (%7 points) it must be %7 x %5: a row per point of %6</source>
        <translation>弧 %1 的矩阵为 %2 x %3；从 %4（%5 个点）到 %6（%7 个点），它必须为 %7 x %5：%6 的每个点对应一行</translation>
    </message>
    <message>
        <source>arc %1 has a matrix entry that is not finite</source>
        <translation>弧 %1 的矩阵含有非有限的元素</translation>
    </message>
    <message>
        <source>row %1 of arc %2 sums to %3, not 1: the map would not keep barycentric coordinates</source>
        <translation>弧 %2 第 %1 行之和为 %3 而不是 1：该映射将无法保持重心坐标</translation>
    </message>
    <message>
        <source>the weight of arc %1 must be a number &gt; 0</source>
        <translation>弧 %1 的权重必须是 &gt; 0 的数</translation>
    </message>
    <message>
        <source>no state %1 to draw; the states are %2</source>
        <translation>没有可绘制的状态 %1；现有状态为 %2</translation>
    </message>
    <message>
        <source>expected a non-empty array of states {&quot;name&quot;: text, &quot;control_points&quot;: [...]}</source>
        <translation>应为非空的状态数组 {&quot;name&quot;: 文本, &quot;control_points&quot;: [...]}</translation>
    </message>
    <message>
        <source>expected an object with &quot;name&quot; and &quot;control_points&quot;</source>
        <translation>应为包含 &quot;name&quot; 和 &quot;control_points&quot; 的对象</translation>
    </message>
    <message>
        <source>unknown field of a state</source>
        <translation>状态的未知字段</translation>
    </message>
    <message>
        <source>expected an array of arcs {&quot;name&quot;, &quot;from&quot;, &quot;to&quot;, &quot;matrix&quot;}</source>
        <translation>应为弧数组 {&quot;name&quot;, &quot;from&quot;, &quot;to&quot;, &quot;matrix&quot;}</translation>
    </message>
    <message>
        <source>expected an object with &quot;from&quot;, &quot;to&quot; and the arc&apos;s map</source>
        <translation>应为包含 &quot;from&quot;、&quot;to&quot; 和弧的映射的对象</translation>
    </message>
    <message>
        <source>unknown field of an arc</source>
        <translation>弧的未知字段</translation>
    </message>
    <message>
        <source>All states</source>
        <translation>所有状态</translation>
    </message>
</context>
<context>
    <name>awb::ComplexBezierItem</name>
    <message>
        <source>Complex Bézier</source>
        <translation>复 Bézier</translation>
    </message>
    <message>
        <source>the parameter t must be a finite complex number</source>
        <translation>参数 t 必须是有限复数</translation>
    </message>
    <message>
        <source>Change t of %1</source>
        <translation>更改 %1 的 t</translation>
    </message>
    <message>
        <source>missing</source>
        <translation type="vanished">缺失</translation>
    </message>
    <message>
        <source>expected [re, im]</source>
        <translation>应为 [re, im]</translation>
    </message>
    <message>
        <source>Split parameter t</source>
        <translation>分割参数 t</translation>
    </message>
    <message>
        <source>Curve</source>
        <translation>曲线</translation>
    </message>
    <message>
        <source>de Casteljau split at a complex t; inside both discs |t| &lt; 1 and |1 − t| &lt; 1 the curve is a fractal (004 §3.7, Fig. 3.3)</source>
        <translation>在复数 t 处做 de Casteljau 分割；在两个圆盘 |t| &lt; 1 与 |1 − t| &lt; 1 的内部，曲线为分形（004 §3.7，Fig. 3.3）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid value for %2</source>
        <translation type="vanished">“%1”不是 %2 的有效值</translation>
    </message>
    <message>
        <source>Complex Bézier curve</source>
        <translation>复 Bézier 曲线</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>Scaled coordinates g(z, 1/(2y)) = Re z + i Im z / (2y), y = %1 (004 eq. (3.40)): as y → 0 the curve approaches the Takagi graph x + i T(x) (Thm 3.7.3, Figs. 3.6–3.8). %2</source>
        <translation>缩放坐标 g(z, 1/(2y)) = Re z + i Im z / (2y)，y = %1（004 eq. (3.40)）：当 y → 0 时，曲线趋近高木函数图像 x + i T(x)（Thm 3.7.3，Figs. 3.6–3.8）。%2</translation>
    </message>
    <message>
        <source>Scaled coordinates apply to t = 1/2 + iy with y ≠ 0 and control points on the real axis (004 Thm 3.7.3); drawn unscaled. %1</source>
        <translation>缩放坐标仅适用于 t = 1/2 + iy（y ≠ 0）且控制点位于实轴上的情形（004 Thm 3.7.3）；按未缩放方式绘制。%1</translation>
    </message>
    <message>
        <source>Change scaled coordinates of %1</source>
        <translation>更改 %1 的缩放坐标</translation>
    </message>
    <message>
        <source>Scaled coordinates g(z, 1/(2y))</source>
        <translation>缩放坐标 g(z, 1/(2y))</translation>
    </message>
    <message>
        <source>Draw Re z + i Im z / (2y) for t = 1/2 + iy: the coordinates of 004 Thm 3.7.3 and Figs. 3.6–3.8, where the curve approaches the Takagi graph</source>
        <translation>对 t = 1/2 + iy 绘制 Re z + i Im z / (2y)：即 004 Thm 3.7.3 和 Figs. 3.6–3.8 中的坐标，曲线在该坐标下趋近高木函数图像</translation>
    </message>
</context>
<context>
    <name>awb::ComplexPlanePicker</name>
    <message>
        <source>Drag t in the complex plane. The attractor exists inside the lens where |t| &lt; 1 and |1 − t| &lt; 1 (both maps contract, 004 Fig. 3.3).</source>
        <translation>在复平面中拖动 t。吸引子存在于满足 |t| &lt; 1 且 |1 − t| &lt; 1 的透镜形区域内（两个映射均为压缩映射，004 Fig. 3.3）。</translation>
    </message>
</context>
<context>
    <name>awb::ControlPointEdits</name>
    <message>
        <source>There is no such point set.</source>
        <translation>没有这个点集。</translation>
    </message>
    <message>
        <source>%1 (%2) has a fixed number of control points.</source>
        <translation>%1（%2）的控制点数目是固定的。</translation>
    </message>
    <message>
        <source>A Bézier curve of degree %1 is refused: %2</source>
        <translation>%1 次 Bézier 曲线被拒绝：%2</translation>
    </message>
    <message>
        <source>There is no point %1.</source>
        <translation>没有点 %1。</translation>
    </message>
    <message>
        <source>Insert control point %1 into %2</source>
        <translation>将控制点 %1 插入 %2</translation>
    </message>
    <message>
        <source>No control point is selected.</source>
        <translation>未选择控制点。</translation>
    </message>
    <message>
        <source>%1 needs at least %2 control points.</source>
        <translation>%1 至少需要 %2 个控制点。</translation>
    </message>
    <message>
        <source>Delete control point %1 of %2</source>
        <translation>删除 %2 的控制点 %1</translation>
    </message>
    <message>
        <source>Delete %1 control points of %2</source>
        <translation>删除 %2 的 %1 个控制点</translation>
    </message>
</context>
<context>
    <name>awb::DensityFile</name>
    <message>
        <source>cannot write %1: the picture is empty</source>
        <translation>无法写入 %1：图像为空</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>cannot write %1: not enough memory</source>
        <translation>无法写入 %1：内存不足</translation>
    </message>
    <message>
        <source>%1; alpha = log(1 + hits) / log(1 + %2); world %3 %4 %5 %6</source>
        <translation>%1；alpha = log(1 + 命中数) / log(1 + %2)；世界坐标 %3 %4 %5 %6</translation>
    </message>
</context>
<context>
    <name>awb::EigenvaluePlotItem</name>
    <message>
        <source>Eigenvalues</source>
        <translation>特征值</translation>
    </message>
    <message>
        <source>S_i, the subdivision matrices</source>
        <translation>S_i，细分矩阵</translation>
    </message>
    <message>
        <source>A_i, the linear parts of M_i</source>
        <translation>A_i，M_i 的线性部分</translation>
    </message>
    <message>
        <source>M_i = P⁻¹S_iP, the lifted maps</source>
        <translation>M_i = P⁻¹S_iP，提升映射</translation>
    </message>
    <message>
        <source>Change the source of %1</source>
        <translation>更改 %1 的来源</translation>
    </message>
    <message>
        <source>Analyse the matrices %1 in %2</source>
        <translation>分析 %2 中的矩阵 %1</translation>
    </message>
    <message>
        <source>M_i is defined only for a lifted subdivision IFS</source>
        <translation>M_i 仅对提升的细分 IFS 有定义</translation>
    </message>
    <message>
        <source>no item is chosen to analyse</source>
        <translation>未选择要分析的对象</translation>
    </message>
    <message>
        <source>there is no item called &quot;%1&quot;</source>
        <translation>没有名为“%1”的对象</translation>
    </message>
    <message>
        <source>&quot;%1&quot; (%2) has no matrices to analyse</source>
        <translation>“%1”（%2）没有可分析的矩阵</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be computed: %2</source>
        <translation>无法计算“%1”：%2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no matrices %2: %3</source>
        <translation>“%1”没有矩阵 %2：%3</translation>
    </message>
    <message>
        <source>Eigenvalue plot</source>
        <translation>特征值图</translation>
    </message>
    <message>
        <source>Analyse the centre of face %1 in %2</source>
        <translation>分析 %2 中面 %1 的中心</translation>
    </message>
    <message>
        <source>Analyse vertex %1 in %2</source>
        <translation>分析 %2 中的顶点 %1</translation>
    </message>
    <message>
        <source>Analyse the mesh&apos;s matrices in %1</source>
        <translation>分析 %1 中网格的矩阵</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a mesh: it has no extraordinary vertices</source>
        <translation>“%1”不是网格：它没有奇异顶点</translation>
    </message>
    <message>
        <source>the centre of face %1 of &quot;%2&quot; is not an extraordinary vertex</source>
        <translation>“%2”中面 %1 的中心不是奇异顶点</translation>
    </message>
    <message>
        <source>vertex %1 of &quot;%2&quot; is not an extraordinary vertex</source>
        <translation>“%2”的顶点 %1 不是奇异顶点</translation>
    </message>
    <message>
        <source>an extraordinary vertex has its local subdivision matrix S only</source>
        <translation>奇异顶点只有其局部细分矩阵 S</translation>
    </message>
    <message>
        <source>expected a vertex or face number (0-based)</source>
        <translation>应为顶点或面的编号（从 0 开始）</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>%1 (missing)</source>
        <translation>%1（缺失）</translation>
    </message>
    <message>
        <source>(the mesh&apos;s matrices)</source>
        <translation>（网格自身的矩阵）</translation>
    </message>
    <message>
        <source>vertex %1 (n = %2)</source>
        <translation>顶点 %1（n = %2）</translation>
    </message>
    <message>
        <source>centre of face %1 (n = %2)</source>
        <translation>面 %1 的中心（n = %2）</translation>
    </message>
    <message>
        <source>centre of face %1 (missing)</source>
        <translation>面 %1 的中心（缺失）</translation>
    </message>
    <message>
        <source>vertex %1 (missing)</source>
        <translation>顶点 %1（缺失）</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <source>The item whose matrices are analysed</source>
        <translation>要分析其矩阵的对象</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>矩阵</translation>
    </message>
    <message>
        <source>S_i: the subdivision matrices (their eigenvalue 1 is affine invariance); A_i: the linear parts of the lifted maps, whose subdominant eigenvalue decides the tangents; M_i: the lifted maps themselves (003 §4, 004 §2.1)</source>
        <translation>S_i：细分矩阵（其特征值 1 对应仿射不变性）；A_i：提升映射的线性部分，其次占优特征值决定切线；M_i：提升映射本身（003 §4，004 §2.1）</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>顶点</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>面</translation>
    </message>
    <message>
        <source>For a mesh surface: the extraordinary vertex whose local subdivision matrix is analysed</source>
        <translation>对于网格曲面：分析其局部细分矩阵的奇异顶点</translation>
    </message>
</context>
<context>
    <name>awb::ExactCurve</name>
    <message>
        <source>Bézier curve c([0, 1])</source>
        <translation>Bézier 曲线 c([0, 1])</translation>
    </message>
    <message>
        <source>Takagi image c(x + 2iy·T(x)), y = %1 (Conj. 3.7.1)</source>
        <translation>Takagi 像 c(x + 2iy·T(x))，y = %1（Conj. 3.7.1）</translation>
    </message>
    <message>
        <source>exact curve: %1</source>
        <translation>精确曲线：%1</translation>
    </message>
    <message>
        <source>Takagi graph x + i T(x), scaled (004 Thm 3.7.3)</source>
        <translation>经缩放的高木函数图像 x + i T(x)（004 Thm 3.7.3）</translation>
    </message>
</context>
<context>
    <name>awb::ExactSpinBox</name>
    <message>
        <source>“%1” is not a number (type e.g. 0.25, 1/3 or sqrt(3)/6).</source>
        <translation>“%1”不是数（请输入例如 0.25、1/3 或 sqrt(3)/6）。</translation>
    </message>
    <message>
        <source>%1 is outside %2 … %3.</source>
        <translation>%1 超出 %2 … %3。</translation>
    </message>
</context>
<context>
    <name>awb::ExampleGallery</name>
    <message>
        <source>Open Example</source>
        <translation>打开示例</translation>
    </message>
    <message>
        <source>One project per figure of the papers, and examples of meshes, masks and animations. An example opens as a copy: Save As keeps it.</source>
        <translation>论文中的每幅插图各对应一个项目，另有网格、掩模和动画的示例。示例以副本形式打开：“另存为”可将其保留。</translation>
    </message>
    <message>
        <source>Filter: a paper (003), a figure, a word (Koch, mesh)…</source>
        <translation>筛选：论文（003）、插图、单词（Koch、mesh）…</translation>
    </message>
    <message>
        <source>No examples installed</source>
        <translation>未安装示例</translation>
    </message>
</context>
<context>
    <name>awb::ExportDialog</name>
    <message>
        <source>Export Figure</source>
        <translation>导出图形</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;LaTeX matrices (*.tex)</source>
        <translation type="vanished">PNG 图像 (*.png);;SVG 绘图 (*.svg);;PDF 文档 (*.pdf);;LaTeX 矩阵 (*.tex)</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;LaTeX matrices (*.tex);;OpenEXR raw density of the attractor, float32 hits per pixel (*.exr)</source>
        <translation>PNG 图像 (*.png);;SVG 绘图 (*.svg);;PDF 文档 (*.pdf);;LaTeX 矩阵 (*.tex);;吸引子的 OpenEXR 原始密度，每像素命中数 float32 (*.exr)</translation>
    </message>
</context>
<context>
    <name>awb::FieldReader</name>
    <message>
        <source>missing</source>
        <translation>缺失</translation>
    </message>
    <message>
        <source>expected a string</source>
        <translation>应为字符串</translation>
    </message>
    <message>
        <source>expected one of %1, got %2</source>
        <translation>应为 %1 之一，实际为 %2</translation>
    </message>
    <message>
        <source>expected an integer</source>
        <translation>应为整数</translation>
    </message>
    <message>
        <source>expected an integer between %1 and %2</source>
        <translation>应为介于 %1 和 %2 之间的整数</translation>
    </message>
    <message>
        <source>expected an array of numbers</source>
        <translation>应为数的数组</translation>
    </message>
    <message>
        <source>expected an array of points [x, y, z]</source>
        <translation>应为点 [x, y, z] 的数组</translation>
    </message>
    <message>
        <source>expected an array of points [x, y]</source>
        <translation>应为点 [x, y] 的数组</translation>
    </message>
    <message>
        <source>expected an array of matrices</source>
        <translation>应为矩阵的数组</translation>
    </message>
    <message>
        <source>expected a matrix: a non-empty array of rows</source>
        <translation>应为矩阵：由行组成的非空数组</translation>
    </message>
    <message>
        <source>expected a row: a non-empty array of numbers</source>
        <translation>应为行：由数组成的非空数组</translation>
    </message>
    <message>
        <source>row %1 has %2 numbers, row 1 has %3</source>
        <translation>第 %1 行有 %2 个数，第 1 行有 %3 个</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>应为对象</translation>
    </message>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 不是有限数</translation>
    </message>
    <message>
        <source>%1 cannot be read as a double-precision number</source>
        <translation>%1 无法读取为双精度数</translation>
    </message>
    <message>
        <source>expected a number</source>
        <translation>应为数</translation>
    </message>
    <message>
        <source>expected a finite number</source>
        <translation>应为有限数</translation>
    </message>
    <message>
        <source>expected a point [x, y, z]</source>
        <translation>应为点 [x, y, z]</translation>
    </message>
    <message>
        <source>expected a point [x, y]</source>
        <translation>应为点 [x, y]</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number (a fraction such as &quot;3/8&quot; or an expression such as &quot;(1 + sqrt(3))/8&quot; is)</source>
        <translation>&quot;%1&quot; 不是数字（数字可以是分数，如 &quot;3/8&quot;，或表达式，如 &quot;(1 + sqrt(3))/8&quot;）</translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation>应为 true 或 false</translation>
    </message>
</context>
<context>
    <name>awb::FigureFile</name>
    <message>
        <source>cannot write %1</source>
        <translation>无法写入 %1</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>the folder %1 does not exist</source>
        <translation>文件夹 %1 不存在</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>它是一个文件夹</translation>
    </message>
    <message>
        <source>the file is read-only</source>
        <translation>该文件是只读的</translation>
    </message>
    <message>
        <source>cannot write %1: it is a folder</source>
        <translation>无法写入 %1：它是一个文件夹</translation>
    </message>
    <message>
        <source>%1 has no suffix: name the format (.png, .svg or .pdf)</source>
        <translation>%1 没有后缀：请指明格式（.png、.svg 或 .pdf）</translation>
    </message>
    <message>
        <source>unknown output format &apos;.%1&apos; (use .png, .svg or .pdf)</source>
        <translation>未知的输出格式“.%1”（请使用 .png、.svg 或 .pdf）</translation>
    </message>
</context>
<context>
    <name>awb::FigureSheet</name>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>No item</source>
        <translation>无对象</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>maps = %1</source>
        <translation>映射数 = %1</translation>
    </message>
    <message>
        <source>control points = %1</source>
        <translation>控制点数 = %1</translation>
    </message>
    <message>
        <source>depth = %1</source>
        <translation>深度 = %1</translation>
    </message>
    <message>
        <source>samples = %1</source>
        <translation>样本数 = %1</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more: see the Matrices dock, or copy them as LaTeX.</source>
        <translation>
            <numerusform>… 另有 %n 个：请查看“矩阵”面板，或将其复制为 LaTeX。</numerusform>
        </translation>
    </message>
    <message>
        <source>Printing %1 was cancelled while the attractor was drawn.</source>
        <translation>绘制吸引子时，%1 的打印已取消。</translation>
    </message>
    <message>
        <source>%1 (%2 × %3):</source>
        <translation>%1（%2 × %3）：</translation>
    </message>
</context>
<context>
    <name>awb::FileWriting</name>
    <message>
        <source>the folder %1 does not exist</source>
        <translation>文件夹 %1 不存在</translation>
    </message>
    <message>
        <source>%1 is not a folder</source>
        <translation>%1 不是文件夹</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>它是一个文件夹</translation>
    </message>
    <message>
        <source>the file is read-only</source>
        <translation>该文件是只读的</translation>
    </message>
    <message>
        <source>cannot create a file in the folder %1: %2</source>
        <translation>无法在文件夹 %1 中创建文件：%2</translation>
    </message>
    <message>
        <source>the folder %1 is read-only</source>
        <translation>文件夹 %1 是只读的</translation>
    </message>
    <message>
        <source>the file is not open</source>
        <translation>文件未打开</translation>
    </message>
</context>
<context>
    <name>awb::FlameExchange</name>
    <message>
        <source>the XML is malformed: %1</source>
        <translation type="vanished">XML 格式错误：%1</translation>
    </message>
    <message>
        <source>%1: the file holds no &lt;flame&gt; element</source>
        <translation type="vanished">%1：文件中没有 &lt;flame&gt; 元素</translation>
    </message>
    <message>
        <source>%1, line %2, column %3: </source>
        <translation>%1，第 %2 行，第 %3 列: </translation>
    </message>
    <message>
        <source>flame %1</source>
        <translation>火焰 %1</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;, final xform</source>
        <translation type="vanished">火焰分形“%1”，最终 xform</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;, xform %2</source>
        <translation type="vanished">火焰分形“%1”，xform %2</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: &lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number</source>
        <translation type="vanished">火焰分形“%1”：&lt;symmetry&gt; 需要 kind=&quot;k&quot;，其中 k 为整数</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: element &lt;%2&gt; ignored</source>
        <translation type="vanished">火焰分形“%1”：已忽略元素 &lt;%2&gt;</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos; has no xform</source>
        <translation type="vanished">火焰分形“%1”没有 xform</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be 6 finite numbers</source>
        <translation type="vanished">%1=&quot;%2&quot; 必须是 6 个有限数值</translation>
    </message>
    <message>
        <source>weight=&quot;%1&quot; must be a finite number &gt;= 0</source>
        <translation type="vanished">weight=&quot;%1&quot; 必须是 &gt;= 0 的有限数值</translation>
    </message>
    <message>
        <source>var1=&quot;%1&quot; names no variation</source>
        <translation type="vanished">var1=&quot;%1&quot; 不是任何变体的名称</translation>
    </message>
    <message>
        <source>variation %1=&quot;%2&quot; is not a number</source>
        <translation type="vanished">变体 %1=&quot;%2&quot; 不是数值</translation>
    </message>
    <message>
        <source>: opacity %1 not kept (every map is drawn)</source>
        <translation type="vanished">：未保留 opacity %1（所有映射均会绘制）</translation>
    </message>
    <message>
        <source>: attribute %1=&quot;%2&quot; ignored</source>
        <translation type="vanished">：已忽略属性 %1=&quot;%2&quot;</translation>
    </message>
    <message numerus="yes">
        <source>: variation %1 dropped (non-linear)</source>
        <translation type="vanished">
            <numerusform>：已舍弃变体 %1（非线性）</numerusform>
        </translation>
    </message>
    <message>
        <source>; its affine part kept as a linear map</source>
        <translation type="vanished">；其仿射部分保留为线性映射</translation>
    </message>
    <message>
        <source>: no variation given; taken as linear</source>
        <translation type="vanished">：未给出变体；按 linear 处理</translation>
    </message>
    <message>
        <source>%1: element &lt;%2&gt; ignored (animation)</source>
        <translation type="vanished">%1：已忽略元素 &lt;%2&gt;（动画）</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: a &lt;color&gt; needs index=&quot;0..255&quot; and rgb=&quot;r g b&quot;</source>
        <translation type="vanished">火焰分形“%1”：&lt;color&gt; 需要 index=&quot;0..255&quot; 和 rgb=&quot;r g b&quot;</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: the palette&apos;s hex digits are not whole colours of %2 digits</source>
        <translation type="vanished">火焰分形“%1”：调色板的十六进制数字不能分成完整的 %2 位颜色值</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: palette entry %2 is not hexadecimal</source>
        <translation type="vanished">火焰分形“%1”：调色板条目 %2 不是十六进制</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: the final xform is not invertible (determinant %2): dropped</source>
        <translation type="vanished">火焰分形“%1”：最终 xform 不可逆（行列式 %2）：已舍弃</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos (chaos) rows forbid some transitions; imported as the plain IFS of its maps, whose attractor contains the flame&apos;s</source>
        <translation type="vanished">火焰分形“%1”：其 xaos（chaos）行禁止了部分转移；已按其映射构成的普通 IFS 导入，该 IFS 的吸引子包含原火焰分形的吸引子</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos (chaos) weights are dropped: the attractor is the same, its measure differs</source>
        <translation type="vanished">火焰分形“%1”：已舍弃其 xaos（chaos）权重：吸引子不变，但其测度不同</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: every xform has weight 0</source>
        <translation>火焰分形“%1”：所有 xform 的权重均为 0</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2 (%3)</source>
        <translation>火焰分形“%1”：%2（%3）</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2</source>
        <translation>火焰“%1”：%2</translation>
    </message>
    <message>
        <source>%1: the file is larger than %2 MB</source>
        <translation type="vanished">%1：文件大于 %2 MB</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation type="vanished">无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is an IFS of space: a flame holds maps of the plane</source>
        <translation type="vanished">%1 是空间 IFS：火焰分形只包含平面映射</translation>
    </message>
    <message>
        <source>the flame&apos;s frame is empty</source>
        <translation>火焰分形的画框为空</translation>
    </message>
    <message>
        <source>: no weight given; taken as 0, as flam3 does (the map is never chosen)</source>
        <translation type="vanished">：未给出权重；按 flam3 的做法取 0（该映射从不被选中）</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its maps do not contract, not even on average (Lyapunov exponent %2 &gt;= 0), so it has no attractor; flam3 draws it only by discarding the points that escape</source>
        <translation type="vanished">火焰 &apos;%1&apos;：其映射不收缩，平均意义下也不收缩（李雅普诺夫指数 %2 &gt;= 0），因此没有吸引子；flam3 只是通过丢弃逃逸的点来绘制它</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: more than %2 xforms (at most %2 maps are supported)</source>
        <translation type="vanished">火焰“%1”：xform 超过 %2 个（最多支持 %2 个映射）</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: &lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %2 to %3, got &apos;%4&apos;</source>
        <translation type="vanished">火焰“%1”：&lt;symmetry&gt; 需要 kind=&quot;k&quot;，取值为 %2 到 %3 的整数，实际为“%4”</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its maps do not contract, not even on average (the Lyapunov exponent of their products, %2, is not clearly negative: not below -0.001), so it may have no attractor; flam3 draws it only by discarding the points that escape</source>
        <translation>火焰“%1”：其映射不收缩，平均意义下也不收缩（其乘积的 Lyapunov 指数 %2 并非明显为负：不低于 -0.001），因此可能没有吸引子；flam3 只是丢弃逃逸的点来绘制它</translation>
    </message>
    <message>
        <source>a flam3 flame</source>
        <translation>flam3 火焰</translation>
    </message>
    <message>
        <source>%1 is an IFS of space: a flam3 flame holds maps of the plane (export it as a Fractint .ifs entry)</source>
        <translation>%1 是空间中的 IFS：flam3 火焰只包含平面映射（请导出为 Fractint .ifs 条目）</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos rows let no xform follow another</source>
        <translation>火焰 &apos;%1&apos;：其 xaos 行不允许任何 xform 跟随在另一个 xform 之后</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: its xaos rows make %2 arcs between its xforms, more than the %3 a controlled IFS may have</source>
        <translation>火焰 &apos;%1&apos;：其 xaos 行在其各 xform 之间产生 %2 条弧，超过了受控IFS所允许的 %3 条</translation>
    </message>
    <message>
        <source>%1: flame &apos;%2&apos; not imported: %3</source>
        <translation>%1：火焰“%2”未导入：%3</translation>
    </message>
</context>
<context>
    <name>awb::FlameFile</name>
    <message>
        <source>the XML is malformed: %1</source>
        <translation>XML 格式错误：%1</translation>
    </message>
    <message>
        <source>%1: the file holds no &lt;flame&gt; element</source>
        <translation>%1：文件中没有 &lt;flame&gt; 元素</translation>
    </message>
    <message>
        <source>%1, line %2, column %3: </source>
        <translation>%1，第 %2 行，第 %3 列: </translation>
    </message>
    <message>
        <source>flame %1</source>
        <translation>火焰 %1</translation>
    </message>
    <message>
        <source>a second &lt;finalxform&gt; (flam3 allows one)</source>
        <translation>第二个 &lt;finalxform&gt;（flam3 只允许一个）</translation>
    </message>
    <message>
        <source>more than %1 xforms</source>
        <translation>超过 %1 个 xform</translation>
    </message>
    <message>
        <source>final xform</source>
        <translation>最终 xform</translation>
    </message>
    <message>
        <source>xform %1</source>
        <translation>xform %1</translation>
    </message>
    <message>
        <source>element &lt;%1&gt; ignored</source>
        <translation>已忽略元素 &lt;%1&gt;</translation>
    </message>
    <message>
        <source>flame &apos;%1&apos;: %2</source>
        <translation>火焰“%1”：%2</translation>
    </message>
    <message>
        <source>xform %1: its xaos row has %2 entries for %3 xforms; the extra ones are ignored, as flam3 does</source>
        <translation>xform %1：其 xaos 行有 %2 项，而 xform 只有 %3 个；多余的项被忽略，与 flam3 相同</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; is not a finite number</source>
        <translation>%1=&quot;%2&quot; 不是有限数</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be %3 finite numbers</source>
        <translation>%1=&quot;%2&quot; 必须是 %3 个有限数</translation>
    </message>
    <message>
        <source>size=&quot;%1&quot; must be two whole numbers from 1 to 32768</source>
        <translation>size=&quot;%1&quot; 必须是 1 到 32768 之间的两个整数</translation>
    </message>
    <message>
        <source>scale=&quot;%1&quot; must be positive</source>
        <translation>scale=&quot;%1&quot; 必须为正数</translation>
    </message>
    <message>
        <source>zoom=&quot;%1&quot; is beyond +-50 (a factor 2^zoom)</source>
        <translation>zoom=&quot;%1&quot; 超出 +-50（系数为 2^zoom）</translation>
    </message>
    <message>
        <source>quality=&quot;%1&quot; must be positive</source>
        <translation>quality=&quot;%1&quot; 必须为正数</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be a whole number from 1 to 64</source>
        <translation>%1=&quot;%2&quot; 必须是 1 到 64 之间的整数</translation>
    </message>
    <message>
        <source>attributes not kept: %1</source>
        <translation>未保留的属性：%1</translation>
    </message>
    <message>
        <source>weight=&quot;%1&quot; is negative</source>
        <translation>weight=&quot;%1&quot; 为负数</translation>
    </message>
    <message>
        <source>color=&quot;%1&quot; must be one or two finite numbers</source>
        <translation>color=&quot;%1&quot; 必须是一个或两个有限数</translation>
    </message>
    <message>
        <source>chaos=&quot;%1&quot; must be at most %2 finite numbers</source>
        <translation>chaos=&quot;%1&quot; 最多只能有 %2 个有限数</translation>
    </message>
    <message>
        <source>chaos=&quot;%1&quot; has a negative entry</source>
        <translation>chaos=&quot;%1&quot; 含有负数项</translation>
    </message>
    <message>
        <source>%1=&quot;%2&quot; must be 6 finite numbers</source>
        <translation>%1=&quot;%2&quot; 必须是 6 个有限数</translation>
    </message>
    <message>
        <source>var1=&quot;%1&quot; names no variation</source>
        <translation>var1=&quot;%1&quot; 不对应任何变体</translation>
    </message>
    <message>
        <source>var=&quot;...&quot; must be %1 finite numbers, one per variation</source>
        <translation>var=&quot;...&quot; 必须是 %1 个有限数，每个变体一个</translation>
    </message>
    <message>
        <source>: a final xform has no weight; weight=&quot;%1&quot; ignored</source>
        <translation>: 最终 xform 没有权重；已忽略 weight=&quot;%1&quot;</translation>
    </message>
    <message>
        <source>: no weight given; taken as 0, as flam3 does (the xform is never chosen)</source>
        <translation>: 未给出权重；与 flam3 相同，按 0 处理（该 xform 永远不会被选中）</translation>
    </message>
    <message>
        <source>: no variation given: as in flam3, every point goes to post(0)</source>
        <translation>: 未给出变体：与 flam3 相同，每个点都映射到 post(0)</translation>
    </message>
    <message>
        <source>: attributes flam3 does not draw, ignored: %1</source>
        <translation>: flam3 不绘制的属性，已忽略：%1</translation>
    </message>
    <message>
        <source>: animation attributes not kept: %1</source>
        <translation>: 未保留的动画属性：%1</translation>
    </message>
    <message>
        <source>: element &lt;%1&gt; ignored (animation)</source>
        <translation>: 已忽略元素 &lt;%1&gt;（动画）</translation>
    </message>
    <message>
        <source>a &lt;color&gt; needs index=&quot;0..255&quot; and rgb=&quot;r g b&quot;</source>
        <translation>&lt;color&gt; 需要 index=&quot;0..255&quot; 和 rgb=&quot;r g b&quot;</translation>
    </message>
    <message>
        <source>a palette of flam3&apos;s palette file (index0) is not kept</source>
        <translation>不保留来自 flam3 调色板文件的调色板（index0）</translation>
    </message>
    <message>
        <source>the palette&apos;s hex digits are not at most 256 colours of %1 digits</source>
        <translation>调色板的十六进制数字不构成至多 256 种各 %1 位的颜色</translation>
    </message>
    <message>
        <source>palette entry %1 is not hexadecimal</source>
        <translation>调色板第 %1 项不是十六进制</translation>
    </message>
    <message>
        <source>&lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %1 to %2</source>
        <translation type="vanished">&lt;symmetry&gt; 需要 kind=&quot;k&quot;，为 %1 到 %2 之间的整数</translation>
    </message>
    <message>
        <source>&lt;symmetry kind=&quot;%1&quot;&gt; makes more than %2 xforms</source>
        <translation>&lt;symmetry kind=&quot;%1&quot;&gt; 生成超过 %2 个 xform</translation>
    </message>
    <message>
        <source>&lt;symmetry&gt; needs kind=&quot;k&quot;, a whole number from %1 to %2, got &apos;%3&apos;</source>
        <translation>&lt;symmetry&gt; 需要 kind=&quot;k&quot;，为 %1 到 %2 之间的整数，实际为“%3”</translation>
    </message>
    <message>
        <source>passes=&quot;%1&quot; must be a whole number from 1 to %2</source>
        <translation>passes=&quot;%1&quot; 必须是 1 到 %2 之间的整数</translation>
    </message>
    <message>
        <source>%1 is larger than 16 MB</source>
        <translation>%1 大于 16 MB</translation>
    </message>
    <message>
        <source>%1 cannot be read</source>
        <translation>无法读取 %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1 has no palette %2</source>
        <translation>%1 中没有调色板 %2</translation>
    </message>
    <message>
        <source>its entry %1 has %2 hex digits, not 256 x 8</source>
        <translation>其条目 %1 有 %2 个十六进制数字，而不是 256 x 8</translation>
    </message>
    <message>
        <source>its entry %1 is not hexadecimal</source>
        <translation>其条目 %1 不是十六进制</translation>
    </message>
    <message>
        <source>palette %1 of flam3&apos;s palette file is not kept: %2</source>
        <translation>未保留 flam3 调色板文件中的调色板 %1：%2</translation>
    </message>
</context>
<context>
    <name>awb::FlameItem</name>
    <message>
        <source>expected 6 numbers in flam3&apos;s order [a, d, b, e, c, f]: x&apos; = a x + b y + c, y&apos; = d x + e y + f</source>
        <translation>应为按 flam3 顺序 [a, d, b, e, c, f] 排列的 6 个数：x&apos; = a x + b y + c, y&apos; = d x + e y + f</translation>
    </message>
    <message>
        <source>expected a non-empty array of xforms</source>
        <translation>应为非空的 xform 数组</translation>
    </message>
    <message>
        <source>%1 xforms: at most %2 are drawn</source>
        <translation>%1 个 xform：最多绘制 %2 个</translation>
    </message>
    <message>
        <source>expected 1536 hexadecimal digits (256 colours rrggbb), got %1</source>
        <translation>应为 1536 个十六进制数字（256 种颜色 rrggbb），实际为 %1 个</translation>
    </message>
    <message>
        <source>colour %1 is not hexadecimal</source>
        <translation>颜色 %1 不是十六进制</translation>
    </message>
    <message>
        <source>expected 256 colours: a string of hexadecimal rrggbb, or [[r, g, b], ...] from 0 to 255</source>
        <translation type="vanished">应为 256 种颜色：十六进制 rrggbb 字符串，或取值 0 到 255 的 [[r, g, b], ...]</translation>
    </message>
    <message>
        <source>expected [r, g, b]</source>
        <translation>应为 [r, g, b]</translation>
    </message>
    <message>
        <source>a channel must be from 0 to 255</source>
        <translation type="vanished">通道值必须在 0 到 255 之间</translation>
    </message>
    <message>
        <source>expected an xform {&quot;coefs&quot;: [...], &quot;variations&quot;: {...}, &quot;weight&quot;: w, ...}</source>
        <translation>应为 xform {&quot;coefs&quot;: [...], &quot;variations&quot;: {...}, &quot;weight&quot;: w, ...}</translation>
    </message>
    <message>
        <source>a weight must not be negative</source>
        <translation>权重不能为负</translation>
    </message>
    <message>
        <source>flam3 has no variation of this name</source>
        <translation>flam3 没有此名称的变体</translation>
    </message>
    <message>
        <source>no variation of flam3 has this parameter</source>
        <translation>flam3 的任何变体都没有此参数</translation>
    </message>
    <message>
        <source>a xaos entry must not be negative</source>
        <translation>xaos 项不能为负</translation>
    </message>
    <message>
        <source>not a field of an xform (coefs, post, variations, parameters, weight, color, color_speed, opacity, animate, chaos, name)</source>
        <translation>不是 xform 的字段（coefs, post, variations, parameters, weight, color, color_speed, opacity, animate, chaos, name）</translation>
    </message>
    <message>
        <source>Flame</source>
        <translation>火焰</translation>
    </message>
    <message>
        <source>the scale (pixels per unit) must be positive</source>
        <translation>比例（每单位像素数）必须为正数</translation>
    </message>
    <message>
        <source>a flame is drawn by random iteration only (its maps are not affine): choose random iteration</source>
        <translation>火焰只能通过随机迭代绘制（其映射不是仿射的）：请选择随机迭代</translation>
    </message>
    <message>
        <source>a flame&apos;s xforms carry their own weights (&quot;xforms&quot;): leave the algorithm&apos;s probabilities empty</source>
        <translation>火焰的 xform 自带权重（&quot;xforms&quot;）：请将算法的概率留空</translation>
    </message>
    <message>
        <source>a flame has no subdivision matrices: its maps are not affine</source>
        <translation>火焰没有细分矩阵：其映射不是仿射的</translation>
    </message>
    <message>
        <source>a fractal flame, drawn by its own chaos game as flam3 draws it; the spectra are those of the xforms&apos; affine (pre) maps, y up</source>
        <translation>分形火焰，按 flam3 的方式由其自身的混沌游戏绘制；谱为各 xform 的仿射（pre）映射的谱，y 轴向上</translation>
    </message>
    <message>
        <source>Change flame of %1</source>
        <translation>更改 %1 的火焰</translation>
    </message>
    <message>
        <source>Xforms</source>
        <translation>Xforms</translation>
    </message>
    <message>
        <source>flam3&apos;s xforms: {&quot;coefs&quot;: [a, d, b, e, c, f], &quot;variations&quot;: {&quot;linear&quot;: 1, ...}, &quot;weight&quot;: w, &quot;color&quot;: c, ...} each</source>
        <translation>flam3 的 xform：每个为 {&quot;coefs&quot;: [a, d, b, e, c, f], &quot;variations&quot;: {&quot;linear&quot;: 1, ...}, &quot;weight&quot;: w, &quot;color&quot;: c, ...}</translation>
    </message>
    <message>
        <source>Final xform</source>
        <translation>最终 xform</translation>
    </message>
    <message>
        <source>Drawn on every point without moving the orbit; null: none</source>
        <translation>作用于每个绘制的点，但不移动轨道；null：无</translation>
    </message>
    <message>
        <source>Palette</source>
        <translation>调色板</translation>
    </message>
    <message>
        <source>256 colours, indexed by the colour coordinate</source>
        <translation>256 种颜色，按颜色坐标索引</translation>
    </message>
    <message>
        <source>Centre x</source>
        <translation>中心 x</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>相机</translation>
    </message>
    <message>
        <source>Centre y</source>
        <translation>中心 y</translation>
    </message>
    <message>
        <source>flam3&apos;s: y grows down the picture</source>
        <translation>flam3 的约定：y 向图像下方增大</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>比例</translation>
    </message>
    <message>
        <source>Pixels per unit (times 2^zoom)</source>
        <translation>每单位像素数（乘以 2^zoom）</translation>
    </message>
    <message>
        <source>Rotation (degrees)</source>
        <translation>旋转（度）</translation>
    </message>
    <message>
        <source>Zoom</source>
        <translation>缩放</translation>
    </message>
    <message>
        <source>Width (pixels)</source>
        <translation>宽度（像素）</translation>
    </message>
    <message>
        <source>Height (pixels)</source>
        <translation>高度（像素）</translation>
    </message>
    <message>
        <source>Quality (samples per pixel)</source>
        <translation>质量（每像素采样数）</translation>
    </message>
    <message>
        <source>Tone</source>
        <translation>色调</translation>
    </message>
    <message>
        <source>Brightness</source>
        <translation>亮度</translation>
    </message>
    <message>
        <source>Gamma</source>
        <translation>伽马</translation>
    </message>
    <message>
        <source>Gamma threshold</source>
        <translation>伽马阈值</translation>
    </message>
    <message>
        <source>Vibrancy</source>
        <translation>鲜艳度</translation>
    </message>
    <message>
        <source>Highlight power</source>
        <translation>高光强度</translation>
    </message>
    <message>
        <source>flam3&apos;s: -1 leaves the highlights as they are</source>
        <translation>flam3 的约定：-1 表示保持高光不变</translation>
    </message>
    <message>
        <source>expected [r, g, b] from 0 to 1</source>
        <translation>应为取值 0 到 1 的 [r, g, b]</translation>
    </message>
    <message>
        <source>Background</source>
        <translation>背景</translation>
    </message>
    <message>
        <source>[r, g, b] from 0 to 1</source>
        <translation>[r, g, b]，取值 0 到 1</translation>
    </message>
    <message>
        <source>Supersample</source>
        <translation>超采样</translation>
    </message>
    <message>
        <source>Filter radius (pixels)</source>
        <translation>滤波半径（像素）</translation>
    </message>
    <message>
        <source>Estimator radius</source>
        <translation>估计器半径</translation>
    </message>
    <message>
        <source>Estimator minimum</source>
        <translation>估计器最小值</translation>
    </message>
    <message>
        <source>Estimator curve</source>
        <translation>估计器曲线</translation>
    </message>
    <message>
        <source>Fractal flame</source>
        <translation>分形火焰</translation>
    </message>
    <message>
        <source>expected 256 colours: a string of hexadecimal rrggbb, or [[r, g, b], ...] from 0 to 1</source>
        <translation>应为 256 种颜色：十六进制 rrggbb 字符串，或取值 0 到 1 的 [[r, g, b], ...]</translation>
    </message>
    <message>
        <source>a channel must be from 0 to 1</source>
        <translation>通道值必须在 0 到 1 之间</translation>
    </message>
    <message>
        <source>Gaussian</source>
        <translation>高斯</translation>
    </message>
    <message>
        <source>Hermite</source>
        <translation>Hermite</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>盒式</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation>三角</translation>
    </message>
    <message>
        <source>Bell</source>
        <translation>钟形</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B 样条</translation>
    </message>
    <message>
        <source>Lanczos 3 (flam3 draws Mitchell)</source>
        <translation>Lanczos 3（flam3 画的是 Mitchell）</translation>
    </message>
    <message>
        <source>Lanczos 2 (flam3 draws Blackman)</source>
        <translation>Lanczos 2（flam3 画的是 Blackman）</translation>
    </message>
    <message>
        <source>Mitchell (flam3 draws Catmull-Rom)</source>
        <translation>Mitchell（flam3 画的是 Catmull-Rom）</translation>
    </message>
    <message>
        <source>Blackman (flam3 draws Hanning)</source>
        <translation>Blackman（flam3 画的是 Hanning）</translation>
    </message>
    <message>
        <source>Catmull-Rom (flam3 draws Hamming)</source>
        <translation>Catmull-Rom（flam3 画的是 Hamming）</translation>
    </message>
    <message>
        <source>Hamming (flam3 draws Lanczos 3)</source>
        <translation>Hamming（flam3 画的是 Lanczos 3）</translation>
    </message>
    <message>
        <source>Hanning (flam3 draws Lanczos 2)</source>
        <translation>Hanning（flam3 画的是 Lanczos 2）</translation>
    </message>
    <message>
        <source>Quadratic</source>
        <translation>二次</translation>
    </message>
    <message>
        <source>Filter shape</source>
        <translation>滤波器形状</translation>
    </message>
    <message>
        <source>flam3&apos;s filter_shape; from Lanczos 3 on, flam3 3.1.1 draws another shape than the name says, and so do we</source>
        <translation>flam3 的 filter_shape；从 Lanczos 3 起，flam3 3.1.1 画的形状与名称不符，本程序也一样</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>阶梯</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>线性</translation>
    </message>
    <message>
        <source>Palette mode</source>
        <translation>调色板模式</translation>
    </message>
    <message>
        <source>flam3&apos;s palette_mode: a hit takes the palette entry at its colour coordinate (step) or between the two entries around it (linear)</source>
        <translation>flam3 的 palette_mode：一次命中取其颜色坐标处的调色板条目（阶梯），或取其两侧条目之间的颜色（线性）</translation>
    </message>
    <message>
        <source>Passes</source>
        <translation>遍数</translation>
    </message>
    <message>
        <source>flam3&apos;s passes: the samples drawn in that many histograms, each log-scaled and density-estimated apart, then summed (a little smoother than one)</source>
        <translation>flam3 的 passes：样本分别绘入这么多个直方图，每个单独做对数缩放和密度估计，然后相加（比一遍略平滑）</translation>
    </message>
</context>
<context>
    <name>awb::FlameXformEditor</name>
    <message>
        <source>The xform to edit; its pre map is its triangle in the attractor view (drag a corner) and in the point table below</source>
        <translation>要编辑的 xform；其前置映射就是吸引子视图中的三角形（拖动一个角）以及下方点表中的点</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>添加</translation>
    </message>
    <message>
        <source>A new xform (linear, weight 1) after the others</source>
        <translation>在其他 xform 之后新建一个 xform（线性，权重 1）</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Weight:</source>
        <translation>权重：</translation>
    </message>
    <message>
        <source>Colour:</source>
        <translation>颜色：</translation>
    </message>
    <message>
        <source>Colour speed:</source>
        <translation>颜色速度：</translation>
    </message>
    <message>
        <source>Opacity:</source>
        <translation>不透明度：</translation>
    </message>
    <message>
        <source>Variation</source>
        <translation>变体</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>权重</translation>
    </message>
    <message>
        <source>The xform&apos;s variations; a weight of 0 removes one</source>
        <translation>该 xform 的变体；权重为 0 即移除</translation>
    </message>
    <message>
        <source>Add a variation…</source>
        <translation>添加变体…</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>The parameters of the xform&apos;s variations</source>
        <translation>该 xform 各变体的参数</translation>
    </message>
    <message>
        <source>A flame needs at least one xform.</source>
        <translation>火焰至少需要一个 xform。</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation type="vanished">颜色</translation>
    </message>
    <message>
        <source>Colour speed</source>
        <translation type="vanished">颜色速度</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation type="vanished">不透明度</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="vanished">%1：%2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1：“%2”不是数字</translation>
    </message>
    <message>
        <source>Xform %1</source>
        <translation>Xform %1</translation>
    </message>
    <message>
        <source>Xform %1: %2</source>
        <translation>Xform %1：%2</translation>
    </message>
    <message>
        <source>Final xform</source>
        <translation>最终 xform</translation>
    </message>
</context>
<context>
    <name>awb::FractalItem</name>
    <message>
        <source>expected an array of %1 numbers</source>
        <translation>应为包含 %1 个数的数组</translation>
    </message>
    <message>
        <source>missing (the custom form needs its maps)</source>
        <translation>缺失（自定义形式需要给出其映射）</translation>
    </message>
    <message>
        <source>expected a non-empty array of maps {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}</source>
        <translation>应为由映射 {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]} 组成的非空数组</translation>
    </message>
    <message>
        <source>expected an object with &quot;A&quot; and &quot;b&quot;</source>
        <translation>应为包含 &quot;A&quot; 和 &quot;b&quot; 的对象</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>缺失</translation>
    </message>
    <message>
        <source>expected a 2 x 2 matrix [[a11, a12], [a21, a22]]</source>
        <translation type="vanished">应为 2 × 2 矩阵 [[a11, a12], [a21, a22]]</translation>
    </message>
    <message>
        <source>the custom form needs at least one map</source>
        <translation>自定义形式至少需要一个映射</translation>
    </message>
    <message>
        <source>map %1 is not a map of the plane</source>
        <translation type="vanished">映射 %1 不是平面上的映射</translation>
    </message>
    <message>
        <source>map %1 has a non-finite entry</source>
        <translation>映射 %1 含有非有限元素</translation>
    </message>
    <message>
        <source>a reference point is not finite</source>
        <translation>某个参考点不是有限的</translation>
    </message>
    <message>
        <source>need at least 3 reference points (000 §4), got %1</source>
        <translation>至少需要 3 个参考点（000 §4），实际为 %1 个</translation>
    </message>
    <message>
        <source>Fractal</source>
        <translation>分形</translation>
    </message>
    <message>
        <source>Change fractal of %1</source>
        <translation>更改 %1 的分形</translation>
    </message>
    <message>
        <source>the %1 reference points and the %2 control points must be equally many</source>
        <translation>%1 个参考点与 %2 个控制点的数目必须相等</translation>
    </message>
    <message>
        <source>the reference points are ill-conditioned: S_i R differs from f_i(R) by up to %1</source>
        <translation>参考点是病态的：S_i R 与 f_i(R) 之差最大可达 %1</translation>
    </message>
    <message>
        <source>Koch curve (000 §4.1)</source>
        <translation>Koch 曲线（000 §4.1）</translation>
    </message>
    <message>
        <source>Sierpinski triangle (000 §4.2)</source>
        <translation>Sierpinski 三角形（000 §4.2）</translation>
    </message>
    <message>
        <source>Own maps</source>
        <translation>自定义映射</translation>
    </message>
    <message>
        <source>The presets use the paper&apos;s printed matrices S_i</source>
        <translation>预设使用论文中给出的矩阵 S_i</translation>
    </message>
    <message>
        <source>Affine weights</source>
        <translation>仿射权重</translation>
    </message>
    <message>
        <source>Nearest control points</source>
        <translation>最近的控制点</translation>
    </message>
    <message>
        <source>Least norm (all points)</source>
        <translation>最小范数（所有点）</translation>
    </message>
    <message>
        <source>How f_i(P_j) is written as an affine combination of the control points (000 eq. (5)): nearest points keep edits local, least norm lets every point move the whole fractal</source>
        <translation>如何将 f_i(P_j) 写成控制点的仿射组合（000 eq. (5)）：“最近的控制点”使编辑保持局部，“最小范数”则让每个点都能移动整个分形</translation>
    </message>
    <message>
        <source>Fractal with control points</source>
        <translation>带控制点的分形</translation>
    </message>
    <message>
        <source>expected a 2 x 2 matrix [[a11, a12], [a21, a22]] or a 3 x 3 one</source>
        <translation>应为 2 x 2 矩阵 [[a11, a12], [a21, a22]] 或 3 x 3 矩阵</translation>
    </message>
    <message>
        <source>expected a %1 x %1 matrix, as the first map</source>
        <translation>应为 %1 x %1 矩阵，与第一个映射相同</translation>
    </message>
    <message>
        <source>map %1 is not a map of the plane or of space like the first</source>
        <translation>映射 %1 不是与第一个映射同维的平面映射或空间映射</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>映射</translation>
    </message>
    <message>
        <source>x ↦ x A + b: {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]} each, or 3 x 3 and 3 numbers in space</source>
        <translation>x ↦ x A + b：每个映射写作 {&quot;A&quot;: [[a11, a12], [a21, a22]], &quot;b&quot;: [b1, b2]}，在空间中则为 3 x 3 矩阵和 3 个数</translation>
    </message>
    <message>
        <source>Reference points</source>
        <translation>参考点</translation>
    </message>
    <message>
        <source>The points the S_i are built for (S_i R = f_i(R)); none: the control points themselves</source>
        <translation>构造 S_i 所依据的点（S_i R = f_i(R)）；不设置：即控制点本身</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>%1 maps: at most %2 maps are supported</source>
        <translation>%1 个映射：最多支持 %2 个映射</translation>
    </message>
</context>
<context>
    <name>awb::IfsExchange</name>
    <message>
        <source>%1, line %2: entry %3: %4 (%5)</source>
        <translation>%1，第 %2 行：条目 %3：%4（%5）</translation>
    </message>
    <message>
        <source>%1, line %2: %3</source>
        <translation>%1，第 %2 行：%3</translation>
    </message>
    <message>
        <source>%1: the file is larger than %2 MB</source>
        <translation>%1：文件大于 %2 MB</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 cannot be computed: %2</source>
        <translation>无法计算 %1：%2</translation>
    </message>
    <message>
        <source>the IFS of %1 acts in a space of dimension %2 that is drawn through a projection (000 §2): a Fractint entry holds maps of the plane or of space only</source>
        <translation type="vanished">%1 的 IFS 作用于 %2 维空间，并通过投影绘制（000 §2）：Fractint 条目只能包含平面或空间中的映射</translation>
    </message>
    <message>
        <source>the IFS of %1 acts in a space of dimension %2 that is drawn through a projection (000 §2), and its maps do not act on the drawn coordinates alone: %3 holds maps of the plane or of space only</source>
        <translation>%1 的 IFS 作用于维数为 %2 的空间，经投影绘制（000 §2），且其映射并非只作用于所绘坐标：%3 只包含平面或空间的映射</translation>
    </message>
    <message>
        <source>%1 is a fractal flame: its xforms are not affine maps, and %2 holds affine maps only (export it as a flam3 flame)</source>
        <translation>%1 是分形火焰：其 xform 不是仿射映射，而 %2 只能保存仿射映射（请将其导出为 flam3 火焰）</translation>
    </message>
</context>
<context>
    <name>awb::InsertControlPointCommand</name>
    <message>
        <source>Add a control point to %1</source>
        <translation>向 %1 添加控制点</translation>
    </message>
</context>
<context>
    <name>awb::InsertItemCommand</name>
    <message>
        <source>Add %1</source>
        <translation>添加 %1</translation>
    </message>
</context>
<context>
    <name>awb::Item</name>
    <message>
        <source>Rename</source>
        <translation>重命名</translation>
    </message>
    <message>
        <source>Change style of %1</source>
        <translation>更改 %1 的样式</translation>
    </message>
    <message>
        <source>Edit animation of %1</source>
        <translation>编辑 %1 的动画</translation>
    </message>
    <message>
        <source>the name cannot be empty</source>
        <translation>名称不能为空</translation>
    </message>
    <message>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 没有参数“%2”</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid value for %2</source>
        <translation>“%1”不是 %2 的有效值</translation>
    </message>
    <message>
        <source>circular reference</source>
        <translation>循环引用</translation>
    </message>
    <message>
        <source>there is not enough memory to compute it</source>
        <translation>内存不足，无法计算</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>By map</source>
        <translation>按映射</translation>
    </message>
    <message>
        <source>By address prefix</source>
        <translation>按地址前缀</translation>
    </message>
    <message>
        <source>Single colour</source>
        <translation>单一颜色</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>颜色</translation>
    </message>
    <message>
        <source>Style</source>
        <translation>样式</translation>
    </message>
    <message>
        <source>The attractor&apos;s colours: by the map that made each point, by the first symbols of its address, or one colour</source>
        <translation>吸引子的颜色：按生成每个点的映射、按点地址的前几个符号，或使用单一颜色</translation>
    </message>
    <message>
        <source>Prefix length</source>
        <translation>前缀长度</translation>
    </message>
    <message>
        <source>Colour by address: how many of its first symbols pick the colour</source>
        <translation>按地址着色：由地址开头的几个符号确定颜色</translation>
    </message>
    <message>
        <source>Point size</source>
        <translation>点大小</translation>
    </message>
    <message>
        <source>Points of the attractor, in pixels</source>
        <translation>吸引子点的大小，单位为像素</translation>
    </message>
    <message>
        <source>expected an array of &quot;#rrggbb&quot; strings</source>
        <translation>应为 &quot;#rrggbb&quot; 字符串的数组</translation>
    </message>
    <message>
        <source>expected a string &quot;#rrggbb&quot;</source>
        <translation>应为字符串 &quot;#rrggbb&quot;</translation>
    </message>
    <message>
        <source>Palette</source>
        <translation>调色板</translation>
    </message>
    <message>
        <source>Own colours, one per map or address prefix (&quot;#rrggbb&quot;); none: the views&apos; palette</source>
        <translation>自定义颜色，每个映射或地址前缀一种（&quot;#rrggbb&quot;）；不设置：使用视图的调色板</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Hits</source>
        <translation>命中</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>密度</translation>
    </message>
    <message>
        <source>Tone</source>
        <translation>色调</translation>
    </message>
    <message>
        <source>Hits: every pixel the attractor reaches (the papers&apos; look); density: the invariant measure by log density; automatic: hits for deterministic, density for random iteration</source>
        <translation>命中：吸引子到达的每个像素（论文中的效果）；密度：以对数密度显示不变测度；自动：确定性迭代用命中，随机迭代用密度</translation>
    </message>
    <message>
        <source>Gamma</source>
        <translation>伽马</translation>
    </message>
    <message>
        <source>Gamma of the density tone</source>
        <translation>密度色调的 gamma</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>动画</translation>
    </message>
    <message>
        <source>%1 is outside the range from %2 to %3</source>
        <translation>%1 超出了 %2 到 %3 的范围</translation>
    </message>
    <message>
        <source>%1 must be a finite number</source>
        <translation>%1 必须是有限数</translation>
    </message>
    <message>
        <source>%1 must be at least %2 and at most %3, not %4</source>
        <translation>%1 必须不小于 %2 且不大于 %3，而不是 %4</translation>
    </message>
    <message>
        <source>%1 must be at least %2, not %3</source>
        <translation>%1 必须不小于 %2，而不是 %3</translation>
    </message>
    <message>
        <source>%1 must be at most %2, not %3</source>
        <translation>%1 必须不大于 %2，而不是 %3</translation>
    </message>
    <message>
        <source>expected [re, im] or a number</source>
        <translation>应为 [re, im] 或一个数</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not %3</source>
        <translation>%1：“%2”不是 %3</translation>
    </message>
    <message>
        <source>a JSON value (%1)</source>
        <translation>JSON 值（%1）</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>数</translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation>整数</translation>
    </message>
    <message>
        <source>one of %1 (or its number from 0)</source>
        <translation>%1 之一（或其从 0 开始的编号）</translation>
    </message>
    <message>
        <source>a complex number (&quot;0.5,0.3&quot; or &quot;0.5+0.3i&quot;)</source>
        <translation>复数（&quot;0.5,0.3&quot; 或 &quot;0.5+0.3i&quot;）</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true 或 false</translation>
    </message>
    <message>
        <source>an item&apos;s type cannot change (%1 to %2): add a new item</source>
        <translation>对象的类型不能更改（%1 改为 %2）：请添加新对象</translation>
    </message>
    <message>
        <source>children are items of their own: add, remove or update them</source>
        <translation>子对象是独立的对象：请分别添加、删除或更新它们</translation>
    </message>
    <message>
        <source>Update %1</source>
        <translation>更新 %1</translation>
    </message>
    <message>
        <source>%1 is shown, not edited</source>
        <translation>%1 仅供显示，不可编辑</translation>
    </message>
    <message>
        <source>Change %1 of %2</source>
        <translation>更改 %2 的 %1</translation>
    </message>
</context>
<context>
    <name>awb::ItemAddress</name>
    <message>
        <source>t: the B-spline&apos;s knot parameter scaled to [0, 1] (the address in base 2)</source>
        <translation>t：B 样条的节点参数缩放到 [0, 1]（即以 2 为基数的地址）</translation>
    </message>
    <message>
        <source>t: the knot parameter scaled to [0, 1] (the address in base 2)</source>
        <translation>t：节点参数缩放到 [0, 1]（即以 2 为基数的地址）</translation>
    </message>
    <message>
        <source>t: the Bernstein parameter (the address in base 2)</source>
        <translation>t：Bernstein 参数（即以 2 为基数的地址）</translation>
    </message>
    <message>
        <source>t: the Bernstein parameter (pieces [0, t], [t, 1] of the split)</source>
        <translation>t：Bernstein 参数（分割所得的片段 [0, t]、[t, 1]）</translation>
    </message>
    <message>
        <source>t: the scheme&apos;s own parameter, the address read in base %1</source>
        <translation>t：细分格式自身的参数，即以 %1 为基数读取的地址</translation>
    </message>
    <message>
        <source>this item is drawn by an automaton: its words are not addresses of one IFS</source>
        <translation>此对象由自动机绘制：其字不是单个 IFS 的地址</translation>
    </message>
    <message>
        <source>a parameter interval is [t0, t1] with two numbers, e.g. [0.25, 0.5]</source>
        <translation>参数区间 [t0, t1] 由两个数组成，例如 [0.25, 0.5]</translation>
    </message>
    <message>
        <source>the parameter interval [%1, %2] must satisfy 0 &lt;= t0 &lt; t1 &lt;= 1</source>
        <translation>参数区间 [%1, %2] 必须满足 0 &lt;= t0 &lt; t1 &lt;= 1</translation>
    </message>
</context>
<context>
    <name>awb::ItemAnalysis</name>
    <message>
        <source>not measured: the flame&apos;s maps are not their affine parts, whose attractor the analysis would count</source>
        <translation>未测量：火焰的映射并不是其仿射部分，而分析所计数的是这些仿射部分的吸引子</translation>
    </message>
</context>
<context>
    <name>awb::ItemController</name>
    <message>
        <source>%1 shows nothing: %2</source>
        <translation>%1 未显示任何内容：%2</translation>
    </message>
    <message>
        <source>%1 has no attractor to draw.</source>
        <translation>%1 没有可绘制的吸引子。</translation>
    </message>
    <message>
        <source>%1 cannot be drawn: %2</source>
        <translation>无法绘制 %1：%2</translation>
    </message>
    <message>
        <source>Regularity: only for subdivision curves</source>
        <translation>正则性：仅适用于细分曲线</translation>
    </message>
    <message>
        <source>Regularity: does not apply (%1)</source>
        <translation type="vanished">正则性：不适用（%1）</translation>
    </message>
    <message>
        <source>complex de Casteljau parameter</source>
        <translation type="vanished">复 de Casteljau 参数</translation>
    </message>
    <message>
        <source>the scheme&apos;s parameters are refused</source>
        <translation type="vanished">细分格式的参数被拒绝</translation>
    </message>
    <message>
        <source>Changing %1 (%2, %3) from %4 to %5 makes row %2 sum to %6, not 1: the rows of a subdivision matrix are affine combinations.

Take the difference %7 from the entry in column %8 (%9 → %10) so that the row sums to 1?</source>
        <translation>将 %1 (%2, %3) 从 %4 改为 %5 会使第 %2 行之和为 %6，而不是 1：细分矩阵的各行是仿射组合。

是否从第 %8 列的元素中减去差值 %7（%9 → %10），使该行之和为 1？</translation>
    </message>
    <message>
        <source>%1 (%2, %3) = %4 was refused: %5</source>
        <translation>%1 (%2, %3) = %4 被拒绝：%5</translation>
    </message>
    <message>
        <source>Insert Point &amp;Before %1</source>
        <translation>在 %1 之前插入点(&amp;B)</translation>
    </message>
    <message>
        <source>Insert Point &amp;After %1</source>
        <translation>在 %1 之后插入点(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Delete Point %1</source>
        <translation>删除点 %1(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Insert Point Here</source>
        <translation>在此处插入点(&amp;I)</translation>
    </message>
    <message>
        <source>&amp;Append Point Here</source>
        <translation>在此处追加点(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Fit View</source>
        <translation>适应视图(&amp;F)</translation>
    </message>
    <message>
        <source>Fᵏ(X₀)</source>
        <translation>Fᵏ(X₀)</translation>
    </message>
    <message>
        <source>Fᵏ(X₀) to the %1</source>
        <translation>Fᵏ(X₀) 到%1</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>顶点 %1</translation>
    </message>
    <message>
        <source>the centre of face %1</source>
        <translation>面 %1 的中心</translation>
    </message>
    <message>
        <source>S at %1 (n = %2)</source>
        <translation>%1 处的 S（n = %2）</translation>
    </message>
    <message>
        <source>The Vertex tab analyses the extraordinary vertices of a mesh surface (Item &gt; Add &gt; Mesh surface, File &gt; Import Mesh).</source>
        <translation>“顶点”标签页分析网格曲面的奇异顶点（对象 &gt; 添加 &gt; 网格曲面，文件 &gt; 导入网格）。</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%2 的%1</translation>
    </message>
    <message>
        <source>Eigenvalues at %1</source>
        <translation>%1 处的特征值</translation>
    </message>
    <message>
        <source>%1 cannot be removed: an IFS of own matrices needs at least two maps</source>
        <translation>无法删除 %1：由自定义矩阵构成的 IFS 至少需要两个映射</translation>
    </message>
    <message>
        <source>No map was added: %1</source>
        <translation>未添加映射：%1</translation>
    </message>
    <message>
        <source>No map was removed: %1</source>
        <translation>未删除映射：%1</translation>
    </message>
    <message>
        <source>Save Regularity Certificate</source>
        <translation>保存正则性证书</translation>
    </message>
    <message>
        <source>Regularity certificate (*.json)</source>
        <translation>正则性证书 (*.json)</translation>
    </message>
    <message>
        <source>No certificate: the regularity of the current curve is not computed yet.</source>
        <translation>没有证书：当前曲线的正则性尚未计算。</translation>
    </message>
    <message>
        <source>No certificate was saved: %1</source>
        <translation>未保存证书：%1</translation>
    </message>
    <message>
        <source>Saved the regularity certificate to %1</source>
        <translation>已将正则性证书保存到 %1</translation>
    </message>
</context>
<context>
    <name>awb::ItemFigure</name>
    <message>
        <source>the 16-bit density is written to PNG files, got &apos;%1&apos;</source>
        <translation>16 位密度写入 PNG 文件，得到的是“%1”</translation>
    </message>
    <message>
        <source>the raw density (.exr, 16-bit PNG) counts an attractor&apos;s points; this item&apos;s figure is a polygon</source>
        <translation>原始密度（.exr、16 位 PNG）统计吸引子的点；此对象的图形是多边形</translation>
    </message>
    <message>
        <source>the rendering was cancelled</source>
        <translation>渲染已取消</translation>
    </message>
    <message>
        <source>item &apos;%1&apos;: %2</source>
        <translation>对象“%1”：%2</translation>
    </message>
    <message>
        <source>depth %1 makes %2 images; at most 4e9 are rendered</source>
        <translation>深度 %1 将产生 %2 个像；最多渲染 4e9 个</translation>
    </message>
    <message>
        <source>the raw density (.exr, 16-bit PNG) is of attractors drawn in the plane; &apos;%1&apos; is drawn in space</source>
        <translation>原始密度（.exr、16 位 PNG）仅适用于平面中绘制的吸引子；“%1”在空间中绘制</translation>
    </message>
    <message>
        <source>the view must be azimuth and elevation in degrees with |elevation| &lt;= 90, got %1, %2</source>
        <translation>视角必须是以度为单位的方位角和仰角，且 |仰角| &lt;= 90，得到的是 %1, %2</translation>
    </message>
    <message>
        <source>%1 random points</source>
        <translation>%1 个随机点</translation>
    </message>
    <message>
        <source>F^%1(X0)</source>
        <translation>F^%1(X0)</translation>
    </message>
    <message>
        <source>, maps %1 of %2</source>
        <translation>，使用映射 %1（共 %2 个）</translation>
    </message>
    <message>
        <source>%1: %2%3 — orthographic view from azimuth %4°, elevation %5°</source>
        <translation>%1：%2%3 — 从方位角 %4°、仰角 %5° 观察的正交视图</translation>
    </message>
    <message>
        <source>%1: %2 random points</source>
        <translation>%1：%2 个随机点</translation>
    </message>
    <message>
        <source>%1: F^%2(X0)</source>
        <translation>%1：F^%2(X0)</translation>
    </message>
    <message>
        <source>%1: polygon after %2 steps</source>
        <translation>%1：%2 步之后的多边形</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is drawn by random iteration only (its maps are not affine): give --samples, not --depth</source>
        <translation>项目“%1”只能通过随机迭代绘制（其映射不是仿射的）：请使用 --samples，而不是 --depth</translation>
    </message>
    <message>
        <source>give --bounds: the item has no frame of its own</source>
        <translation>请给出 --bounds：该项没有自己的画框</translation>
    </message>
    <message>
        <source>%1 samples; at most %2</source>
        <translation>%1 个样本；最多 %2</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation type="vanished">无法写入 %1</translation>
    </message>
</context>
<context>
    <name>awb::JunctionSpec</name>
    <message>
        <source>the junction parameter %1 must be a finite number</source>
        <translation>拼接参数 %1 必须是有限数</translation>
    </message>
    <message>
        <source>%1 = %2 is outside (%3, %4): %5</source>
        <translation>%1 = %2 不在 (%3, %4) 内：%5</translation>
    </message>
</context>
<context>
    <name>awb::MainWindow</name>
    <message>
        <source>Attractor Workbench projects (*.awb);;All files (*)</source>
        <translation>Attractor Workbench 项目 (*.awb);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>自动保存失败：%1</translation>
    </message>
    <message>
        <source>&lt;original&gt;</source>
        <translation>&lt;原始状态&gt;</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Cancel the analysis</source>
        <translation>取消分析</translation>
    </message>
    <message>
        <source>Drawing %p%</source>
        <translation>正在绘制 %p%</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Stop drawing the attractor (Esc); F5 draws it again</source>
        <translation>停止绘制吸引子（Esc）；按 F5 重新绘制</translation>
    </message>
    <message>
        <source>Drawing the attractor for the figure…</source>
        <translation>正在为图形绘制吸引子…</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>图形</translation>
    </message>
    <message>
        <source>Drawing stopped; press F5 to draw again.</source>
        <translation>绘制已停止；按 F5 重新绘制。</translation>
    </message>
    <message>
        <source>Analysis %p%</source>
        <translation>分析 %p%</translation>
    </message>
    <message>
        <source>Analysis cancelled.</source>
        <translation>分析已取消。</translation>
    </message>
    <message>
        <source>Row sum</source>
        <translation>行和</translation>
    </message>
    <message>
        <source>Edit refused</source>
        <translation>编辑被拒绝</translation>
    </message>
    <message>
        <source>x = %1, y = %2</source>
        <translation>x = %1，y = %2</translation>
    </message>
    <message>
        <source>Drawing failed: %1</source>
        <translation>绘制失败：%1</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>新建(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>还原(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>关闭(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Print…</source>
        <translation>打印(&amp;P)…</translation>
    </message>
    <message>
        <source>Print Pre&amp;view…</source>
        <translation>打印预览(&amp;V)…</translation>
    </message>
    <message>
        <source>Ctrl+Alt+P</source>
        <translation>Ctrl+Alt+P</translation>
    </message>
    <message>
        <source>Print to P&amp;DF…</source>
        <translation>打印为 PDF(&amp;D)…</translation>
    </message>
    <message>
        <source>Print to PDF</source>
        <translation>打印为 PDF</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>&amp;Export Figure…</source>
        <translation>导出图形(&amp;E)…</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Export &amp;Points…</source>
        <translation>导出点(&amp;P)…</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>Pre&amp;ferences…</source>
        <translation>首选项(&amp;F)…</translation>
    </message>
    <message>
        <source>Copy Matrices as &amp;LaTeX</source>
        <translation>将矩阵复制为 LaTeX(&amp;L)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <source>The current item has no matrices.</source>
        <translation>当前对象没有矩阵。</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n matrices as LaTeX (amsmath bmatrix).</source>
        <translation>
            <numerusform>已将 %n 个矩阵复制为 LaTeX（amsmath bmatrix）。</numerusform>
        </translation>
    </message>
    <message>
        <source>D&amp;uplicate Item</source>
        <translation>复制对象(&amp;U)</translation>
    </message>
    <message>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <source>&amp;Delete Item</source>
        <translation>删除对象(&amp;D)</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>放大(&amp;I)</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>缩小(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>适应窗口(&amp;F)</translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <source>&amp;Stop Drawing</source>
        <translation>停止绘制(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Draw Again</source>
        <translation>重新绘制(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Play/Pause Animation</source>
        <translation>播放/暂停动画(&amp;P)</translation>
    </message>
    <message>
        <source>S&amp;top Animation</source>
        <translation>停止动画(&amp;T)</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>重置布局(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;About Attractor Workbench</source>
        <translation>关于 Attractor Workbench(&amp;A)</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>Nothing to %1 (%2)</source>
        <translation>没有可%1的操作（%2）</translation>
    </message>
    <message>
        <source>%1 %2 (%3)</source>
        <translation>%1 %2（%3）</translation>
    </message>
    <message>
        <source>&amp;Control Polygon</source>
        <translation>控制多边形(&amp;C)</translation>
    </message>
    <message>
        <source>Control &amp;Net (3D)</source>
        <translation>控制网格（3D）(&amp;N)</translation>
    </message>
    <message>
        <source>Subdivided &amp;Mesh (3D)</source>
        <translation>细分网格（3D）(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;Attractor (3D)</source>
        <translation>吸引子（3D）(&amp;A)</translation>
    </message>
    <message>
        <source>A&amp;xes (3D)</source>
        <translation>坐标轴（3D）(&amp;X)</translation>
    </message>
    <message>
        <source>&amp;Bounding Box (3D)</source>
        <translation>包围盒（3D）(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Perspective (3D)</source>
        <translation>透视投影（3D）(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Start Set</source>
        <translation>初始集(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Exact Curve</source>
        <translation>精确曲线(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>网格线(&amp;G)</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>项目</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>属性</translation>
    </message>
    <message>
        <source>Undo History</source>
        <translation>撤销历史</translation>
    </message>
    <message>
        <source>Spectrum</source>
        <translation>谱</translation>
    </message>
    <message>
        <source>Matrices</source>
        <translation>矩阵</translation>
    </message>
    <message>
        <source>Analysis</source>
        <translation>分析</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>动画</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Item</source>
        <translation>对象(&amp;I)</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>添加(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>Four-point &amp;Regularity Chart…</source>
        <translation>四点格式正则性图表(&amp;R)…</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source> Hutchinson step: </source>
        <translation> Hutchinson 步数：</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>  Subdivision steps: </source>
        <translation>  细分步数：</translation>
    </message>
    <message>
        <source>Classic subdivision polygons beside the IFS attractor</source>
        <translation>在 IFS 吸引子旁显示经典细分多边形</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <source>%1[*] — Attractor Workbench</source>
        <translation>%1[*] — Attractor Workbench</translation>
    </message>
    <message>
        <source>Cubic B-spline</source>
        <translation>三次 B 样条</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>打开项目</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>保存项目</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <source>The project &quot;%1&quot; has unsaved changes. Save them?</source>
        <translation>项目“%1”有未保存的更改。是否保存？</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>项目另存为</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>还原</translation>
    </message>
    <message>
        <source>Discard all changes and reload %1?</source>
        <translation>放弃所有更改并重新加载 %1？</translation>
    </message>
    <message>
        <source>Printing cancelled.</source>
        <translation>打印已取消。</translation>
    </message>
    <message>
        <source>Print</source>
        <translation>打印</translation>
    </message>
    <message>
        <source>The printer could not be started.</source>
        <translation>无法启动打印机。</translation>
    </message>
    <message>
        <source>A .tex file holds the matrices only: choose the Matrices view, or .png, .svg or .pdf for a picture.</source>
        <translation>.tex 文件只包含矩阵：请选择“矩阵”视图；若要导出图片，请选择 .png、.svg 或 .pdf。</translation>
    </message>
    <message>
        <source>The current item has no matrices to export.</source>
        <translation>当前对象没有可导出的矩阵。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>无法写入 %1：%2。</translation>
    </message>
    <message>
        <source>Unknown format &quot;%1&quot;: use .png, .svg or .pdf (.tex for the matrices).</source>
        <translation type="vanished">未知格式“%1”：请使用 .png、.svg 或 .pdf（矩阵使用 .tex）。</translation>
    </message>
    <message>
        <source>Exporting %1 was cancelled while the attractor was drawn.</source>
        <translation>绘制吸引子时，%1 的导出已取消。</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="vanished">已导出 %1</translation>
    </message>
    <message>
        <source>About Attractor Workbench</source>
        <translation>关于 Attractor Workbench</translation>
    </message>
    <message>
        <source>Attractor Workbench %1

Subdivision curves as attractors of iterated function systems: control points, subdivision matrices, spectra and figures.</source>
        <translation>Attractor Workbench %1

作为迭代函数系统吸引子的细分曲线：控制点、细分矩阵、谱与图形。</translation>
    </message>
    <message>
        <source>Spectra of %1</source>
        <translation>%1 的谱</translation>
    </message>
    <message>
        <source>Bicubic B-spline</source>
        <translation>双三次 B 样条</translation>
    </message>
    <message>
        <source>Loop (box spline)</source>
        <translation>Loop（箱样条）</translation>
    </message>
    <message>
        <source>Kobbelt √3</source>
        <translation>Kobbelt √3</translation>
    </message>
    <message>
        <source>%1, %2 layout</source>
        <translation>%1，%2 布局</translation>
    </message>
    <message>
        <source>%1 surface</source>
        <translation>%1 曲面</translation>
    </message>
    <message>
        <source>duplicate</source>
        <translation>副本</translation>
    </message>
    <message>
        <source>Duplicate Item</source>
        <translation>复制对象</translation>
    </message>
    <message>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <source>an unsaved project</source>
        <translation>未保存的项目</translation>
    </message>
    <message>
        <source>Recover Project</source>
        <translation>恢复项目</translation>
    </message>
    <message>
        <source>Attractor Workbench did not shut down properly. A recovery copy of %1 from %2 exists. Recover it? (Discard deletes the copy.)</source>
        <translation>Attractor Workbench 未正常关闭。存在 %1 的恢复副本（保存于 %2）。是否恢复？（“放弃”将删除该副本。）</translation>
    </message>
    <message>
        <source>The recovery copy cannot be read: %1</source>
        <translation>无法读取恢复副本：%1</translation>
    </message>
    <message>
        <source>The recovery copy cannot be read: %1

It was kept as %2.</source>
        <translation>无法读取恢复副本：%1

已将其保留为 %2。</translation>
    </message>
    <message>
        <source>Export Points</source>
        <translation>导出点</translation>
    </message>
    <message>
        <source>The current item has no attractor whose points could be exported.</source>
        <translation>当前对象没有可导出点的吸引子。</translation>
    </message>
    <message>
        <source>Exported the points to %1</source>
        <translation>已将点导出到 %1</translation>
    </message>
    <message>
        <source>The current item has no attractor.</source>
        <translation>当前对象没有吸引子。</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>System Default</source>
        <translation>系统默认</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <source>The language changes when Attractor Workbench is started again.</source>
        <translation>重新启动 Attractor Workbench 后，语言更改才会生效。</translation>
    </message>
    <message>
        <source>Built with Qt %1 (running on Qt %2), Eigen %3 and QCustomPlot %4.</source>
        <translation>基于 Qt %1（运行于 Qt %2）、Eigen %3 和 QCustomPlot %4 构建。</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>Open E&amp;xample</source>
        <translation>打开示例(&amp;X)</translation>
    </message>
    <message>
        <source>Draw Fᵏ(X₀) of the start set X₀ as vectors</source>
        <translation>以矢量绘制初始集 X₀ 的 Fᵏ(X₀)</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <source>No examples installed</source>
        <translation>未安装示例</translation>
    </message>
    <message>
        <source>Open Example</source>
        <translation>打开示例</translation>
    </message>
    <message>
        <source>Opened the example %1 (a copy: Save As keeps it)</source>
        <translation>已打开示例 %1（副本：另存为可保留）</translation>
    </message>
    <message>
        <source>Projects and figures with their item (*.awb *.png *.svg);;Attractor Workbench projects (*.awb);;Exported figures (*.png *.svg);;All files (*)</source>
        <translation type="vanished">项目及带有对象的图形 (*.awb *.png *.svg);;Attractor Workbench 项目 (*.awb);;导出的图形 (*.png *.svg);;所有文件 (*)</translation>
    </message>
    <message>
        <source>&amp;Import Mesh…</source>
        <translation>导入网格(&amp;I)…</translation>
    </message>
    <message>
        <source>Import Mesh</source>
        <translation>导入网格</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.off *.ply);;Wavefront OBJ (*.obj);;OFF (*.off);;PLY (*.ply)</source>
        <translation>网格 (*.obj *.off *.ply);;Wavefront OBJ (*.obj);;OFF (*.off);;PLY (*.ply)</translation>
    </message>
    <message>
        <source>Catmull–Clark (any polygons)</source>
        <translation>Catmull–Clark（任意多边形）</translation>
    </message>
    <message>
        <source>Loop (triangles only)</source>
        <translation>Loop（仅三角形）</translation>
    </message>
    <message>
        <source>Subdivision scheme:</source>
        <translation>细分格式：</translation>
    </message>
    <message>
        <source>Cube (Catmull–Clark)</source>
        <translation>立方体（Catmull–Clark）</translation>
    </message>
    <message>
        <source>Tetrahedron (Loop)</source>
        <translation>四面体（Loop）</translation>
    </message>
    <message>
        <source>Octahedron (Loop)</source>
        <translation>八面体（Loop）</translation>
    </message>
    <message>
        <source>Icosahedron (Loop)</source>
        <translation>二十面体（Loop）</translation>
    </message>
    <message>
        <source>Pentagonal prism (Catmull–Clark)</source>
        <translation>五棱柱（Catmull–Clark）</translation>
    </message>
    <message>
        <source>Open grid (Catmull–Clark)</source>
        <translation>开放网格（Catmull–Clark）</translation>
    </message>
    <message>
        <source>Grid of mixed diagonals (Loop)</source>
        <translation>混合对角线网格（Loop）</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>顶点</translation>
    </message>
    <message>
        <source>Valences</source>
        <translation>顶点价</translation>
    </message>
    <message>
        <source>%1: its spectrum, verdict and characteristic map are in the Spectrum, Matrices and Analysis docks</source>
        <translation>%1：其谱、判定结果和特征映射见“谱”“矩阵”和“分析”面板</translation>
    </message>
    <message>
        <source>Export &amp;Mesh…</source>
        <translation>导出网格(&amp;M)…</translation>
    </message>
    <message>
        <source>Export Mesh writes a mesh surface; %1 is a %2</source>
        <translation>“导出网格”写出的是网格曲面；而 %1 的类型为 %2</translation>
    </message>
    <message>
        <source>Export Mesh writes a mesh surface: choose one first</source>
        <translation>“导出网格”写出的是网格曲面：请先选择一个网格曲面</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Export Mesh</source>
        <translation>导出网格</translation>
    </message>
    <message>
        <source>Steps of %1 before every vertex is moved to its limit position:</source>
        <translation>将每个顶点移到其极限位置之前的 %1 细分步数：</translation>
    </message>
    <message>
        <source>Wavefront OBJ (*.obj)</source>
        <translation>Wavefront OBJ (*.obj)</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
    <message>
        <source>Copy Matrices as &amp;MATLAB</source>
        <translation>将矩阵复制为 MATLAB(&amp;M)</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n matrices as MATLAB cell arrays (for jsr() of the JSR toolbox).</source>
        <translation>
            <numerusform>已将 %n 个矩阵复制为 MATLAB 元胞数组（用于 JSR 工具箱的 jsr()）。</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>导入(&amp;T)…</translation>
    </message>
    <message>
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <source>Export &amp;Item As…</source>
        <translation>将对象导出为(&amp;L)…</translation>
    </message>
    <message>
        <source>%1: no entry could be imported</source>
        <translation>%1：未能导入任何条目</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>导入 %1</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>导入</translation>
    </message>
    <message>
        <source>Everything Attractor Workbench imports (*.ifs *.obj *.off *.ply);;Fractint IFS (*.ifs);;Meshes (*.obj *.off *.ply)</source>
        <translation type="vanished">Attractor Workbench 可导入的所有文件 (*.ifs *.obj *.off *.ply);;Fractint IFS (*.ifs);;网格 (*.obj *.off *.ply)</translation>
    </message>
    <message>
        <source>Imported the other entries; these were left out:</source>
        <translation type="vanished">已导入其余条目；以下条目被略过：</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>已导入 %1</translation>
    </message>
    <message>
        <source>Export Item As writes an item with maps: choose one first</source>
        <translation>“将对象导出为”写出的是带映射的对象：请先选择一个这样的对象</translation>
    </message>
    <message>
        <source>%1 has no matrices to export</source>
        <translation>%1 没有可导出的矩阵</translation>
    </message>
    <message>
        <source>%1: Export Item As writes .ifs (Fractint) or .m (MATLAB) files</source>
        <translation type="vanished">%1：“将对象导出为”只能写出 .ifs（Fractint）或 .m（MATLAB）文件</translation>
    </message>
    <message>
        <source>Export Item As</source>
        <translation>将对象导出为</translation>
    </message>
    <message>
        <source>Fractint IFS (*.ifs);;MATLAB cell arrays of the matrices (*.m)</source>
        <translation type="vanished">Fractint IFS (*.ifs);;矩阵的 MATLAB 元胞数组 (*.m)</translation>
    </message>
    <message>
        <source>Everything Attractor Workbench imports (*.ifs *.flame *.flam3 *.obj *.off *.ply);;Fractint IFS (*.ifs);;Fractal flames: flam3, Apophysis, JWildfire (*.flame *.flam3);;Meshes (*.obj *.off *.ply)</source>
        <translation>Attractor Workbench 可导入的所有文件 (*.ifs *.flame *.flam3 *.obj *.off *.ply);;Fractint IFS (*.ifs);;火焰分形：flam3、Apophysis、JWildfire (*.flame *.flam3);;网格 (*.obj *.off *.ply)</translation>
    </message>
    <message>
        <source>Imported the others; these were left out:</source>
        <translation>其余已导入；以下各项被略过：</translation>
    </message>
    <message>
        <source>Imported with these losses:</source>
        <translation>已导入，但有以下损失：</translation>
    </message>
    <message>
        <source>%1: Export Item As writes .ifs (Fractint), .flame (flam3) or .m (MATLAB) files</source>
        <translation>%1：“将对象导出为”只能写入 .ifs（Fractint）、.flame（flam3）或 .m（MATLAB）文件</translation>
    </message>
    <message>
        <source>Fractint IFS (*.ifs);;Fractal flame for flam3-render, Apophysis, JWildfire (*.flame);;MATLAB cell arrays of the matrices (*.m)</source>
        <translation>Fractint IFS (*.ifs);;用于 flam3-render、Apophysis、JWildfire 的火焰分形 (*.flame);;矩阵的 MATLAB 元胞数组 (*.m)</translation>
    </message>
    <message>
        <source>An .exr file holds the raw density of an attractor drawn in the plane: choose the Attractor view of such an item.</source>
        <translation>.exr 文件保存平面中绘制的吸引子的原始密度：请选择此类对象的吸引子视图。</translation>
    </message>
    <message>
        <source>Unknown format &quot;%1&quot;: use .png, .svg or .pdf (.tex for the matrices, .exr for the attractor&apos;s raw density).</source>
        <translation>未知格式“%1”：请使用 .png、.svg 或 .pdf（矩阵使用 .tex，吸引子的原始密度使用 .exr）。</translation>
    </message>
    <message>
        <source>Projects and figures with their item (*.awb *.png *.svg);;Attractor Workbench projects (*.awb);;Exported figures (*.png *.svg);;Other tools&apos; IFS files, as a new project (*.ifs *.flame *.flam3);;All files (*)</source>
        <translation>项目及带有对象的图形 (*.awb *.png *.svg);;Attractor Workbench 项目 (*.awb);;导出的图形 (*.png *.svg);;其他工具的 IFS 文件，作为新项目 (*.ifs *.flame *.flam3);;所有文件 (*)</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>工具(&amp;T)</translation>
    </message>
    <message>
        <source>Python Console</source>
        <translation>Python 控制台</translation>
    </message>
    <message>
        <source>Save &amp;Recording…</source>
        <translation>保存录制(&amp;R)…</translation>
    </message>
    <message>
        <source>Save the edits since the project was opened as a Python script that replays them on the file</source>
        <translation>将打开项目以来的编辑保存为 Python 脚本，可在该文件上重放</translation>
    </message>
    <message>
        <source>&amp;Clear Recording</source>
        <translation>清除录制(&amp;C)</translation>
    </message>
    <message>
        <source>Start the recording again from the document as it is now</source>
        <translation>从文档当前状态重新开始录制</translation>
    </message>
    <message>
        <source>Save Recording</source>
        <translation>保存录制</translation>
    </message>
    <message>
        <source>Python scripts (*.py)</source>
        <translation>Python 脚本 (*.py)</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n recorded edit(s) to %1</source>
        <translation>
            <numerusform>已将 %n 项录制的编辑保存到 %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Run Python &amp;Script…</source>
        <translation>运行 Python 脚本(&amp;S)…</translation>
    </message>
    <message>
        <source>Run a Python script on the open document, in the Python console</source>
        <translation>在 Python 控制台中对打开的文档运行 Python 脚本</translation>
    </message>
    <message>
        <source>Run Python Script</source>
        <translation>运行 Python 脚本</translation>
    </message>
    <message>
        <source>&amp;Gallery…</source>
        <translation>图库(&amp;G)…</translation>
    </message>
    <message>
        <source>The examples as thumbnails: the papers&apos; figures, meshes, masks</source>
        <translation>以缩略图显示示例：论文插图、网格、掩模</translation>
    </message>
    <message>
        <source>Exported the figure to %1</source>
        <translation>已将图形导出到 %1</translation>
    </message>
    <message>
        <source>000 Schaefer, Levin, Goldman: Subdivision Schemes and Attractors</source>
        <translation>000 Schaefer、Levin、Goldman：细分格式与吸引子</translation>
    </message>
    <message>
        <source>001 Li et al.: Normal Vector Based Subdivision</source>
        <translation>001 Li 等：基于法向量的细分</translation>
    </message>
    <message>
        <source>002 John: All Bézier Curves Are Attractors</source>
        <translation>002 John：所有 Bézier 曲线都是吸引子</translation>
    </message>
    <message>
        <source>003 BCIFS Junction Curves</source>
        <translation>003 BCIFS 拼接曲线</translation>
    </message>
    <message>
        <source>004 Ptáčková: Fractals and Splines</source>
        <translation>004 Ptáčková：分形与样条</translation>
    </message>
    <message>
        <source>Meshes</source>
        <translation>网格</translation>
    </message>
    <message>
        <source>Masks, Animations and Other Tools&apos; Files</source>
        <translation>掩模、动画及其他工具的文件</translation>
    </message>
    <message>
        <source>All %1 faces are triangles: Loop keeps them triangles (Catmull–Clark would make each one three quads around a new valence-3 vertex).

Subdivision scheme:</source>
        <translation>全部 %1 个面都是三角形：Loop 会保持其为三角形（Catmull–Clark 会把每个面变成围绕一个新的 3 价顶点的三个四边形）。

细分格式：</translation>
    </message>
    <message>
        <source>Regularity &amp;Atlas…</source>
        <translation>正则性图谱(&amp;A)…</translation>
    </message>
    <message>
        <source>Where the selected curve&apos;s family of schemes is C^k, over one or two of its parameters (on a Dask cluster)</source>
        <translation>所选曲线的细分格式族在其一个或两个参数上何处为 C^k（在 Dask 集群上计算）</translation>
    </message>
    <message>
        <source>Automaton</source>
        <translation>自动机</translation>
    </message>
    <message>
        <source>Edge %1–%2: sharpness %3 (Item &gt; Crease Edge… changes it)</source>
        <translation>边 %1–%2：锐度 %3（可用“对象 &gt; 折痕边…”更改）</translation>
    </message>
    <message>
        <source>&amp;Crease Edge…</source>
        <translation>折痕边(&amp;C)…</translation>
    </message>
    <message>
        <source>The sharpness of the mesh edge clicked in the 3D view</source>
        <translation>在三维视图中点击的网格边的锐度</translation>
    </message>
    <message>
        <source>Sharpen &amp;Vertex…</source>
        <translation>锐化顶点(&amp;V)…</translation>
    </message>
    <message>
        <source>The corner sharpness of the mesh vertex clicked in the 3D view</source>
        <translation>在三维视图中点击的网格顶点的角点锐度</translation>
    </message>
    <message>
        <source>Sharp features belong to mesh surfaces: choose one first</source>
        <translation>尖锐特征属于网格曲面：请先选择一个</translation>
    </message>
    <message>
        <source>Click an edge of the control mesh in the 3D view first</source>
        <translation>请先在三维视图中点击控制网格的一条边</translation>
    </message>
    <message>
        <source>Click a vertex of the control mesh in the 3D view first</source>
        <translation>请先在三维视图中点击控制网格的一个顶点</translation>
    </message>
    <message>
        <source>Crease Edge</source>
        <translation>折痕边</translation>
    </message>
    <message>
        <source>Sharpness of the edge from vertex %1 to vertex %2 (0: smooth; the crease rules for that many levels; 10: for ever):</source>
        <translation>从顶点 %1 到顶点 %2 的边的锐度（0：光滑；在这么多层内使用折痕规则；10：永久）：</translation>
    </message>
    <message>
        <source>Sharpen Vertex</source>
        <translation>锐化顶点</translation>
    </message>
    <message>
        <source>Sharpness of vertex %1 (0: smooth; a corner for that many levels; 10: for ever):</source>
        <translation>顶点 %1 的锐度（0：光滑；在这么多层内为角点；10：永久）：</translation>
    </message>
    <message>
        <source>Not repaired: %1</source>
        <translation>未修复：%1</translation>
    </message>
    <message>
        <source>%1

Repair the mesh? These changes are well defined:

%2</source>
        <translation>%1

修复该网格？以下更改是明确定义的：

%2</translation>
    </message>
    <message>
        <source>Even repaired: %1</source>
        <translation>修复后仍然：%1</translation>
    </message>
    <message>
        <source>Repaired: %1</source>
        <translation>已修复：%1</translation>
    </message>
    <message>
        <source>Imported with these losses and changes:</source>
        <translation>导入时有以下损失和更改：</translation>
    </message>
    <message>
        <source>The mesh is %1.

Repair it instead? These changes are well defined:

%2

No imports it as it is.</source>
        <translation>该网格为%1。

改为修复它吗？以下修改是明确定义的：

%2

选择“否”则按原样导入。</translation>
    </message>
    <message>
        <source>The mesh is %1.</source>
        <translation>该网格为%1。</translation>
    </message>
    <message>
        <source>Face %1: a hole (Item &gt; Toggle Hole fills it)</source>
        <translation>面 %1：孔（对象 &gt; 切换孔 会将其填上）</translation>
    </message>
    <message>
        <source>Face %1 (Item &gt; Toggle Hole makes it a hole)</source>
        <translation>面 %1（对象 &gt; 切换孔 会将其设为孔）</translation>
    </message>
    <message>
        <source>Toggle &amp;Hole</source>
        <translation>切换孔(&amp;H)</translation>
    </message>
    <message>
        <source>Make the mesh face clicked in the 3D view a hole, or fill it</source>
        <translation>将在三维视图中点击的网格面设为孔，或将其填上</translation>
    </message>
    <message>
        <source>Click inside a face of the control mesh in the 3D view first</source>
        <translation>请先在三维视图中点击控制网格的一个面内部</translation>
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
        <translation>%1 %2 %3i（模为 %4）</translation>
    </message>
    <message>
        <source>Sum of row %1: %2</source>
        <translation>第 %1 行之和：%2</translation>
    </message>
    <message>
        <source>Sum of column %1: %2</source>
        <translation>第 %1 列之和：%2</translation>
    </message>
    <message>
        <source>“%1” is not a finite number: %2, row %3, column %4 was not changed.</source>
        <translation>“%1”不是有限数：%2 第 %3 行第 %4 列未更改。</translation>
    </message>
    <message>
        <source>A block</source>
        <translation>A 块</translation>
    </message>
    <message>
        <source>b row</source>
        <translation>b 行</translation>
    </message>
    <message>
        <source>fixed part of the lifted map</source>
        <translation>提升映射的固定部分</translation>
    </message>
    <message>
        <source>— &lt;span style=&apos;background:#e2ecfa&apos;&gt;&amp;nbsp;A&amp;nbsp;&lt;/span&gt; block, &lt;span style=&apos;background:#fcecd6&apos;&gt;&amp;nbsp;b&amp;nbsp;&lt;/span&gt; row</source>
        <translation>— &lt;span style=&apos;background:#e2ecfa&apos;&gt;&amp;nbsp;A&amp;nbsp;&lt;/span&gt; 块，&lt;span style=&apos;background:#fcecd6&apos;&gt;&amp;nbsp;b&amp;nbsp;&lt;/span&gt; 行</translation>
    </message>
    <message>
        <source>(complex entries)</source>
        <translation>（复数元素）</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Remove the map %1 from the IFS (one undo step)</source>
        <translation>从 IFS 中删除映射 %1（一个撤销步骤）</translation>
    </message>
    <message>
        <source>Add a Map</source>
        <translation>添加映射</translation>
    </message>
    <message>
        <source>A new map S_(p+1), a copy of the last one to edit cell by cell (one undo step)</source>
        <translation>新映射 S_(p+1)，为最后一个映射的副本，可逐个单元格编辑（一个撤销步骤）</translation>
    </message>
</context>
<context>
    <name>awb::MeshInputs</name>
    <message>
        <source>%1 vertices; a mesh item takes at most %2</source>
        <translation>%1 个顶点；网格对象最多接受 %2 个</translation>
    </message>
    <message>
        <source>%1 faces; a mesh item takes at most %2</source>
        <translation>%1 个面；网格对象最多接受 %2 个</translation>
    </message>
</context>
<context>
    <name>awb::Messages</name>
    <message>
        <source>… and %1 more lines: Show Details… lists them all.</source>
        <translation>… 还有 %1 行：“显示详情…”会将其全部列出。</translation>
    </message>
    <message>
        <source>Show Details… shows the whole text.</source>
        <translation>“显示详情…”可显示全文。</translation>
    </message>
</context>
<context>
    <name>awb::MoveControlPointsCommand</name>
    <message numerus="yes">
        <source>Move %n control points of %1</source>
        <translation>
            <numerusform>移动 %1 的 %n 个控制点</numerusform>
        </translation>
    </message>
    <message>
        <source>Move a control point of %1</source>
        <translation>移动 %1 的一个控制点</translation>
    </message>
</context>
<context>
    <name>awb::MoveItemCommand</name>
    <message>
        <source>Move %1</source>
        <translation>移动 %1</translation>
    </message>
</context>
<context>
    <name>awb::NormalVectorItem</name>
    <message>
        <source>Normal-vector curve</source>
        <translation>法向量曲线</translation>
    </message>
    <message>
        <source>Change normal-vector scheme of %1</source>
        <translation>更改 %1 的法向量格式</translation>
    </message>
    <message>
        <source>the normal-vector scheme is not linear: it has no subdivision matrices (001 eq. (1))</source>
        <translation>法向量格式不是线性的：它没有细分矩阵（001 eq. (1)）</translation>
    </message>
    <message>
        <source>No equivalent IFS: %1</source>
        <translation>没有等价的 IFS：%1</translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation type="vanished">应为 true 或 false</translation>
    </message>
    <message>
        <source>expected an array of sign rules</source>
        <translation>应为符号规则的数组</translation>
    </message>
    <message>
        <source>expected one of &quot;%1&quot;</source>
        <translation>应为 &quot;%1&quot; 之一</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>细分格式</translation>
    </message>
    <message>
        <source>Own rules</source>
        <translation>自定义规则</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步数</translation>
    </message>
    <message>
        <source>Subdivision steps of the polygon shown</source>
        <translation>所显示多边形的细分步数</translation>
    </message>
    <message>
        <source>Normal direction</source>
        <translation>法向</translation>
    </message>
    <message>
        <source>Counter-clockwise (positive)</source>
        <translation>逆时针（正向）</translation>
    </message>
    <message>
        <source>Clockwise (negative)</source>
        <translation>顺时针（负向）</translation>
    </message>
    <message>
        <source>Closed polygon</source>
        <translation>闭合多边形</translation>
    </message>
    <message>
        <source>α%1</source>
        <translation>α%1</translation>
    </message>
    <message>
        <source>Rules</source>
        <translation>规则</translation>
    </message>
    <message>
        <source>Position of new point %1 along the edge (001 eq. (1))</source>
        <translation type="vanished">新点 %1 沿边的位置（001 eq. (1)）</translation>
    </message>
    <message>
        <source>β%1</source>
        <translation>β%1</translation>
    </message>
    <message>
        <source>Displacement of new point %1 along the normal</source>
        <translation type="vanished">新点 %1 沿法向的位移</translation>
    </message>
    <message>
        <source>Signs of β</source>
        <translation>β 的符号</translation>
    </message>
    <message>
        <source>How the sign of β alternates: &quot;constant&quot;, &quot;edge-alternating&quot;, &quot;level-edge-alternating&quot; or &quot;level-alternating&quot;; none, one, or one per rule</source>
        <translation>β 符号的交替方式：&quot;constant&quot;、&quot;edge-alternating&quot;、&quot;level-edge-alternating&quot; 或 &quot;level-alternating&quot;；不设置、设置一个，或每条规则一个</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
</context>
<context>
    <name>awb::NormalVectorSpec</name>
    <message>
        <source>unknown preset &quot;%1&quot;</source>
        <translation>未知预设“%1”</translation>
    </message>
    <message>
        <source>%1 steps: at least 0 and at most %2 are allowed</source>
        <translation>步数 %1：允许的范围为 0 到 %2</translation>
    </message>
    <message>
        <source>need at least 2 rules (p &gt;= 2), got %1</source>
        <translation>至少需要 2 条规则（p &gt;= 2），实际为 %1 条</translation>
    </message>
    <message>
        <source>%1 values of beta for %2 of alpha: need one per rule</source>
        <translation>beta 有 %1 个值而 alpha 有 %2 个：每条规则需要一个</translation>
    </message>
    <message>
        <source>%1 signs for %2 rules: give none, one, or one per rule</source>
        <translation>%2 条规则有 %1 个符号：请不给出、给出一个，或每条规则给出一个</translation>
    </message>
    <message>
        <source>%1_%2 is not a finite number</source>
        <translation>%1_%2 不是有限数</translation>
    </message>
</context>
<context>
    <name>awb::PaletteDialog</name>
    <message>
        <source>Map Colours</source>
        <translation>映射颜色</translation>
    </message>
    <message>
        <source>The colour of the points each map f&lt;sub&gt;i&lt;/sub&gt; makes (Style: colour by map or by address).</source>
        <translation>每个映射 f&lt;sub&gt;i&lt;/sub&gt; 所生成的点的颜色（样式：按映射或按地址着色）。</translation>
    </message>
    <message>
        <source>Colour of map %1</source>
        <translation>映射 %1 的颜色</translation>
    </message>
    <message>
        <source>Map %1:</source>
        <translation>映射 %1：</translation>
    </message>
    <message>
        <source>Use the &amp;Default Colours</source>
        <translation>使用默认颜色(&amp;D)</translation>
    </message>
</context>
<context>
    <name>awb::PointExport</name>
    <message>
        <source>cannot write the points: %1</source>
        <translation>无法写入这些点：%1</translation>
    </message>
    <message>
        <source>--address needs an item drawn by one IFS; this one is drawn by an automaton</source>
        <translation>--address 需要由单个 IFS 绘制的对象；此对象由自动机绘制</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is drawn by an automaton: PLY export covers items with one IFS</source>
        <translation>“%1”由自动机绘制：PLY 导出仅支持由单个 IFS 绘制的对象</translation>
    </message>
    <message>
        <source>wrote %1 points, expected %2</source>
        <translation>写入了 %1 个点，应为 %2 个</translation>
    </message>
    <message>
        <source>this item is a fractal flame: its points come from its own chaos game, not from iterating maps (render its picture instead)</source>
        <translation>此项目是分形火焰：其点来自自身的混沌游戏，而不是迭代映射（请改为渲染其图像）</translation>
    </message>
</context>
<context>
    <name>awb::PointExportDialog</name>
    <message>
        <source>Export Points of %1</source>
        <translation>导出 %1 的点</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <source>CSV text: x, y[, z], map, view</source>
        <translation>CSV 文本：x, y[, z], map, view</translation>
    </message>
    <message>
        <source>PLY point cloud: x, y, z, map colour, map</source>
        <translation>PLY 点云：x, y, z, 映射颜色, map</translation>
    </message>
    <message>
        <source>F&amp;ormat:</source>
        <translation>格式(&amp;O)：</translation>
    </message>
    <message>
        <source>The points of F^k(X0): every image of the start set&apos;s vertices after k steps of the Hutchinson operator</source>
        <translation>F^k(X0) 的点：初始集顶点经过 Hutchinson 算子 k 步迭代后的所有像</translation>
    </message>
    <message>
        <source>&amp;Depth k:</source>
        <translation>深度 k(&amp;D)：</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>导出(&amp;E)</translation>
    </message>
    <message>
        <source>Export Points</source>
        <translation>导出点</translation>
    </message>
    <message>
        <source>CSV text (*.csv);;PLY point cloud (*.ply)</source>
        <translation>CSV 文本 (*.csv);;PLY 点云 (*.ply)</translation>
    </message>
    <message>
        <source>The number of points depends on the automaton.</source>
        <translation>点的数目取决于自动机。</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>%1 个点</translation>
    </message>
    <message>
        <source> — too many (at most %1): choose a smaller depth.</source>
        <translation> — 过多（最多 %1 个）：请选择较小的深度。</translation>
    </message>
    <message>
        <source>%1 cannot be computed: %2</source>
        <translation>无法计算 %1：%2</translation>
    </message>
    <message>
        <source>Start set: %1</source>
        <translation>初始集：%1</translation>
    </message>
    <message>
        <source>Depth %1 gives %2 points, more than %3: choose a smaller depth.</source>
        <translation>深度 %1 产生 %2 个点，超过 %3 个：请选择较小的深度。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Writing the points of %1…</source>
        <translation>正在写入 %1 的点…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Exporting the points was cancelled; nothing was written.</source>
        <translation>导出点已取消；未写入任何内容。</translation>
    </message>
</context>
<context>
    <name>awb::PreferencesDialog</name>
    <message>
        <source>auto</source>
        <translation>自动</translation>
    </message>
</context>
<context>
    <name>awb::Project</name>
    <message>
        <source>Item</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>the name cannot be empty</source>
        <translation>名称不能为空</translation>
    </message>
    <message>
        <source>another item is already called &quot;%1&quot;</source>
        <translation>已有另一个对象名为“%1”</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n items</source>
        <translation>
            <numerusform>移除 %n 个对象</numerusform>
        </translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>将 %1 重命名为 %2</translation>
    </message>
    <message>
        <source>the project has no file name yet: use &quot;Save As&quot;</source>
        <translation>项目还没有文件名：请使用“另存为”</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>awb::ProjectIO</name>
    <message>
        <source>%1: cannot save: %2</source>
        <translation>%1：无法保存：%2</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1：无法打开：%2</translation>
    </message>
    <message>
        <source>%1: the file is %2 MB; project files larger than %3 MB are refused (a project is at most a few MB)</source>
        <translation>%1：文件大小为 %2 MB；大于 %3 MB 的项目文件将被拒绝（一个项目最多只有几 MB）</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
    <message>
        <source>%1: the file is empty</source>
        <translation>%1：文件为空</translation>
    </message>
    <message>
        <source>%1: the file holds only white space</source>
        <translation>%1：文件只包含空白字符</translation>
    </message>
    <message>
        <source>%1: the file is UTF-16 or UTF-32 text; project files are UTF-8 (save it again as UTF-8)</source>
        <translation>%1：文件是 UTF-16 或 UTF-32 文本；项目文件应为 UTF-8（请将其重新保存为 UTF-8）</translation>
    </message>
    <message>
        <source>%1: expected a JSON object at the top level</source>
        <translation>%1：顶层应为 JSON 对象</translation>
    </message>
    <message>
        <source>%1: not valid JSON: %2 at line %3, column %4</source>
        <translation>%1：不是有效的 JSON：%2，位于第 %3 行第 %4 列</translation>
    </message>
    <message>
        <source>expected &quot;%1&quot;: this is not an Attractor Workbench project</source>
        <translation>应为 &quot;%1&quot;：这不是 Attractor Workbench 项目</translation>
    </message>
    <message>
        <source>%1: the file has format version %2, written by a newer version of Attractor Workbench; this version reads format version %3 only. Please update the application.</source>
        <translation>%1：该文件的格式版本为 %2，由较新版本的 Attractor Workbench 写入；此版本只能读取格式版本 %3。请更新本程序。</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>缺失</translation>
    </message>
    <message>
        <source>expected an array</source>
        <translation>应为数组</translation>
    </message>
    <message>
        <source>%1: field &quot;%2&quot;: %3</source>
        <translation>%1：字段 &quot;%2&quot;：%3</translation>
    </message>
    <message>
        <source>item %1</source>
        <translation>第 %1 个对象</translation>
    </message>
    <message>
        <source>%1: %2: field &quot;%3&quot;: %4</source>
        <translation>%1：%2：字段 &quot;%3&quot;：%4</translation>
    </message>
    <message>
        <source>field &quot;%1&quot;: %2</source>
        <translation>字段 &quot;%1&quot;：%2</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>应为对象</translation>
    </message>
    <message>
        <source>unknown item type %1; this version knows %2</source>
        <translation>未知的对象类型 %1；此版本支持的类型为 %2</translation>
    </message>
    <message>
        <source>another item is already called %1</source>
        <translation>已有另一个对象名为 %1</translation>
    </message>
    <message>
        <source>expected an array of items</source>
        <translation>应为对象的数组</translation>
    </message>
    <message>
        <source>expected an array of lifted points [x, y, c1, ...]</source>
        <translation>应为提升点 [x, y, c1, ...] 的数组</translation>
    </message>
    <message>
        <source>expected a lifted point [x, y, c1, ...]</source>
        <translation>应为提升点 [x, y, c1, ...]</translation>
    </message>
    <message>
        <source>expected an array of &quot;#rrggbb&quot; strings</source>
        <translation type="vanished">应为 &quot;#rrggbb&quot; 字符串的数组</translation>
    </message>
    <message>
        <source>expected a string &quot;#rrggbb&quot;</source>
        <translation type="vanished">应为字符串 &quot;#rrggbb&quot;</translation>
    </message>
    <message>
        <source>a &quot;vertex-limits&quot; start set has no points (it starts at the limit positions of the mesh&apos;s vertices)</source>
        <translation>&quot;vertex-limits&quot; 初始集没有点（它从网格顶点的极限位置开始）</translation>
    </message>
    <message>
        <source>the item</source>
        <translation>该项</translation>
    </message>
    <message>
        <source>expected an array of net point indices [0, 9, 18]</source>
        <translation>应为网格点索引数组 [0, 9, 18]</translation>
    </message>
    <message>
        <source>%1 net point indices; a start set takes at most %2</source>
        <translation>%1 个网格点索引；初始集最多只能有 %2 个</translation>
    </message>
    <message>
        <source>expected a net point index (an integer from 0)</source>
        <translation>应为网格点索引（从 0 开始的整数）</translation>
    </message>
</context>
<context>
    <name>awb::ProjectTreeModel</name>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message numerus="yes">
        <source>Move %n items</source>
        <translation>
            <numerusform>移动 %n 个对象</numerusform>
        </translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>移动 %1</translation>
    </message>
</context>
<context>
    <name>awb::PropertiesWidget</name>
    <message>
        <source>Value refused</source>
        <translation>值被拒绝</translation>
    </message>
    <message>
        <source>%1 cannot be set to %2.</source>
        <translation>无法将 %1 设为 %2。</translation>
    </message>
    <message>
        <source>No item selected.</source>
        <translation>未选择对象。</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation type="vanished">名称(&amp;N)：</translation>
    </message>
    <message>
        <source>The name is empty or already taken.</source>
        <translation type="vanished">名称为空或已被占用。</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
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
        <translation type="vanished">初始集 X0</translation>
    </message>
    <message>
        <source>Point</source>
        <translation type="vanished">点</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation type="vanished">线段</translation>
    </message>
    <message>
        <source>Triangle</source>
        <translation type="vanished">三角形</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation type="vanished">多边形</translation>
    </message>
    <message>
        <source>Points</source>
        <translation type="vanished">点集</translation>
    </message>
    <message>
        <source>Lifted points</source>
        <translation type="vanished">提升点</translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation type="vanished">类型：</translation>
    </message>
    <message>
        <source>Drag its vertices in the attractor view.</source>
        <translation type="vanished">在吸引子视图中拖动其顶点。</translation>
    </message>
    <message>
        <source>Points of the lifted space of 000 §2: x, y, then the extra coordinates of the lifting, the homogeneous 1 implied. Commas between coordinates, &apos;;&apos; between points.</source>
        <translation type="vanished">000 §2 提升空间中的点：先是 x、y，然后是提升的附加坐标，齐次坐标 1 隐含。坐标之间用逗号分隔，点之间用“;”分隔。</translation>
    </message>
    <message>
        <source>Lifted:</source>
        <translation type="vanished">提升点：</translation>
    </message>
    <message>
        <source>The start set was refused.</source>
        <translation type="vanished">初始集被拒绝。</translation>
    </message>
    <message>
        <source>The item has no control points.</source>
        <translation type="vanished">该对象没有控制点。</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number.</source>
        <translation type="vanished">“%1”不是数。</translation>
    </message>
    <message>
        <source>Algorithm</source>
        <translation type="vanished">算法</translation>
    </message>
    <message>
        <source>Deterministic</source>
        <translation type="vanished">确定性</translation>
    </message>
    <message>
        <source>Random (chaos game)</source>
        <translation type="vanished">随机（混沌游戏）</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation type="vanished">模式：</translation>
    </message>
    <message>
        <source>Depth:</source>
        <translation type="vanished">深度：</translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation type="vanished">样本数：</translation>
    </message>
    <message>
        <source>Style</source>
        <translation type="vanished">样式</translation>
    </message>
    <message>
        <source>By map</source>
        <translation type="vanished">按映射</translation>
    </message>
    <message>
        <source>By address prefix</source>
        <translation type="vanished">按地址前缀</translation>
    </message>
    <message>
        <source>Single colour</source>
        <translation type="vanished">单一颜色</translation>
    </message>
    <message>
        <source>Colour:</source>
        <translation type="vanished">颜色：</translation>
    </message>
    <message>
        <source>Prefix length:</source>
        <translation type="vanished">前缀长度：</translation>
    </message>
    <message>
        <source>Point size:</source>
        <translation type="vanished">点大小：</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>Set %1 (%2)</source>
        <translation>点集 %1（%2）</translation>
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
        <translation>“%1”不是有限数。</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>添加</translation>
    </message>
    <message>
        <source>Append a point after the last one</source>
        <translation>在最后一个点之后追加一个点</translation>
    </message>
    <message>
        <source>Insert</source>
        <translation>插入</translation>
    </message>
    <message>
        <source>Insert a point before the selected one (halfway to its predecessor)</source>
        <translation>在所选点之前插入一个点（位于它与前一个点的中点）</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Delete the selected points (one undo step)</source>
        <translation>删除所选的点（一次撤销即可恢复）</translation>
    </message>
    <message>
        <source>The colour of each map&apos;s points: click to choose</source>
        <translation>每个映射所生成点的颜色：单击以选择</translation>
    </message>
    <message>
        <source>Default…</source>
        <translation>默认…</translation>
    </message>
    <message>
        <source>Own…</source>
        <translation>自定义…</translation>
    </message>
    <message>
        <source>Map colours:</source>
        <translation>映射颜色：</translation>
    </message>
    <message>
        <source>Eigenvalues</source>
        <translation type="vanished">特征值</translation>
    </message>
    <message>
        <source>The item whose matrices are analysed</source>
        <translation type="vanished">要分析其矩阵的对象</translation>
    </message>
    <message>
        <source>S_i: the subdivision matrices (their eigenvalue 1 is affine invariance); A_i: the linear parts of the lifted maps, whose subdominant eigenvalue decides the tangents; M_i: the lifted maps themselves (003 §4, 004 §2.1)</source>
        <translation type="vanished">S_i：细分矩阵（其特征值 1 对应仿射不变性）；A_i：提升映射的线性部分，其次占优特征值决定切线；M_i：提升映射本身（003 §4，004 §2.1）</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation type="vanished">来源：</translation>
    </message>
    <message>
        <source>Matrices:</source>
        <translation type="vanished">矩阵：</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="vanished">（无）</translation>
    </message>
    <message>
        <source>%1 (missing)</source>
        <translation type="vanished">%1（缺失）</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation type="vanished">深度</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation type="vanished">样本数</translation>
    </message>
    <message>
        <source>Prefix length</source>
        <translation type="vanished">前缀长度</translation>
    </message>
    <message>
        <source>Point size</source>
        <translation type="vanished">点大小</translation>
    </message>
    <message>
        <source>%1 matrices %2_i, %3 eigenvalues, plotted in the centre; click an eigenvalue to mark its map (its matrices in the Matrices dock).</source>
        <translation>%1 个矩阵 %2_i，%3 个特征值，绘制在中央；点击特征值以标记其映射（其矩阵见矩阵面板）。</translation>
    </message>
    <message>
        <source>Vertex limits</source>
        <translation type="vanished">顶点极限位置</translation>
    </message>
    <message>
        <source>Vertex limits: the exact limit positions of the mesh&apos;s vertices, where its IFS with condensation starts. Drag the control points in the 3D view; click a purple diamond to analyse that extraordinary vertex.</source>
        <translation type="vanished">顶点极限位置：网格顶点的精确极限位置，即其带凝聚集的 IFS 的起点。在 3D 视图中拖动控制点；单击紫色菱形可分析该奇异顶点。</translation>
    </message>
    <message>
        <source>For a mesh surface: the extraordinary vertex whose local subdivision matrix is analysed</source>
        <translation type="vanished">对于网格曲面：分析其局部细分矩阵的奇异顶点</translation>
    </message>
    <message>
        <source>Vertex:</source>
        <translation type="vanished">顶点：</translation>
    </message>
    <message>
        <source>(the mesh&apos;s matrices)</source>
        <translation type="vanished">（网格自身的矩阵）</translation>
    </message>
    <message>
        <source>vertex %1 (n = %2)</source>
        <translation type="vanished">顶点 %1（n = %2）</translation>
    </message>
    <message>
        <source>centre of face %1 (n = %2)</source>
        <translation type="vanished">面 %1 的中心（n = %2）</translation>
    </message>
    <message>
        <source>centre of face %1 (missing)</source>
        <translation type="vanished">面 %1 的中心（缺失）</translation>
    </message>
    <message>
        <source>vertex %1 (missing)</source>
        <translation type="vanished">顶点 %1（缺失）</translation>
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
        <translation>Python：project、item、awb（attractor_workbench）和 np</translation>
    </message>
    <message>
        <source># Python %1 console: `project` is the open document, `item` the current item, `awb` the attractor_workbench module (help(awb)). Edits are undoable; every edit made in the window is shown below as the line that makes it (Tools &gt; Save Recording).</source>
        <translation># Python %1 控制台：`project` 是打开的文档，`item` 是当前项，`awb` 是 attractor_workbench 模块（help(awb)）。编辑可以撤销；在窗口中所做的每个编辑都会在下方显示为执行它的那一行（工具 &gt; 保存录制）。</translation>
    </message>
    <message>
        <source># The recording starts again, from a new project.</source>
        <translation># 录制重新开始，从新项目开始。</translation>
    </message>
    <message>
        <source># The recording starts again, from %1.</source>
        <translation># 录制重新开始，从 %1 开始。</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source># Running %1</source>
        <translation># 正在运行 %1</translation>
    </message>
</context>
<context>
    <name>awb::Recovery</name>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1：无法打开：%2</translation>
    </message>
    <message>
        <source>%1: not an Attractor Workbench recovery file</source>
        <translation>%1：不是 Attractor Workbench 恢复文件</translation>
    </message>
    <message>
        <source>%1: written by a newer version of Attractor Workbench</source>
        <translation>%1：由较新版本的 Attractor Workbench 写入</translation>
    </message>
    <message>
        <source>%1: field &quot;project&quot;: expected an object</source>
        <translation>%1：字段 &quot;project&quot;：应为对象</translation>
    </message>
</context>
<context>
    <name>awb::RegularityAtlasWindow</name>
    <message>
        <source>Regularity Atlas</source>
        <translation>正则性图谱</translation>
    </message>
    <message>
        <source>Item:</source>
        <translation>项：</translation>
    </message>
    <message>
        <source>The mask with the parameters written into it, e.g. &quot;v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v&quot; (the six-point family).</source>
        <translation>写入了参数的掩模，例如“v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v”（六点格式族）。</translation>
    </message>
    <message>
        <source>&amp;Mask:</source>
        <translation>掩模(&amp;M)：</translation>
    </message>
    <message>
        <source>The parameter&apos;s name: omega, a, b, or a name in the mask.</source>
        <translation>参数名：omega、a、b，或掩模中的某个名称。</translation>
    </message>
    <message>
        <source>Grid values, both ends included.</source>
        <translation>网格取值，包含两端。</translation>
    </message>
    <message>
        <source>from</source>
        <translation>从</translation>
    </message>
    <message>
        <source>to</source>
        <translation>到</translation>
    </message>
    <message>
        <source>values</source>
        <translation>个值</translation>
    </message>
    <message>
        <source>&amp;Second parameter:</source>
        <translation>第二个参数(&amp;S)：</translation>
    </message>
    <message>
        <source>&amp;Parameter:</source>
        <translation>参数(&amp;P)：</translation>
    </message>
    <message>
        <source>The class the atlas refines around: its C^k boundaries.</source>
        <translation>图谱围绕其 C^k 边界进行细化的类。</translation>
    </message>
    <message>
        <source>One parameter: each boundary&apos;s bracket narrows to this width.</source>
        <translation>单参数：每条边界所在的区间收窄到此宽度。</translation>
    </message>
    <message>
        <source>Two parameters: how many times a cell whose corners disagree is split.</source>
        <translation>双参数：角点结果不一致的单元被细分的次数。</translation>
    </message>
    <message>
        <source>Class:</source>
        <translation>类：</translation>
    </message>
    <message>
        <source>Tolerance:</source>
        <translation>容差：</translation>
    </message>
    <message>
        <source>Refinement levels:</source>
        <translation>细化层数：</translation>
    </message>
    <message>
        <source>Atlas:</source>
        <translation>图谱：</translation>
    </message>
    <message numerus="yes">
        <source>A local Dask cluster (%n worker(s))</source>
        <translation>
            <numerusform>本地 Dask 集群（%n 个工作进程）</numerusform>
        </translation>
    </message>
    <message>
        <source>The Dask scheduler named in Preferences (none set)</source>
        <translation>首选项中指定的 Dask 调度器（未设置）</translation>
    </message>
    <message>
        <source>The Dask scheduler at %1</source>
        <translation>位于 %1 的 Dask 调度器</translation>
    </message>
    <message>
        <source>This machine, one process (no Dask)</source>
        <translation>本机，单进程（不使用 Dask）</translation>
    </message>
    <message>
        <source>&amp;Run on:</source>
        <translation>运行于(&amp;R)：</translation>
    </message>
    <message>
        <source>&amp;Compute</source>
        <translation>计算(&amp;C)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>(none: select a subdivision curve)</source>
        <translation>（无：请选择一条细分曲线）</translation>
    </message>
    <message>
        <source>Write the parameters&apos; names into the mask (&quot;v, 0, w, 0, 1/2 - w - v, 1, …&quot;), give their ranges, and Compute.</source>
        <translation>将参数名写入掩模（“v, 0, w, 0, 1/2 - w - v, 1, …”），给出其取值范围，然后单击“计算”。</translation>
    </message>
    <message>
        <source>Give the parameters&apos; ranges and Compute: each point is a certified joint spectral radius, computed by python3 -m attractor_workbench.atlas.</source>
        <translation>给出参数的取值范围并单击“计算”：每个点都是一个经认证的联合谱半径，由 python3 -m attractor_workbench.atlas 计算。</translation>
    </message>
    <message>
        <source>Select a subdivision curve first: the atlas moves its scheme&apos;s parameters.</source>
        <translation>请先选择一条细分曲线：图谱会改变其格式的参数。</translation>
    </message>
    <message>
        <source>No Dask scheduler is set: name one in Edit &gt; Preferences, or run on a local cluster.</source>
        <translation>未设置 Dask 调度器：请在“编辑 &gt; 首选项”中指定一个，或在本地集群上运行。</translation>
    </message>
    <message>
        <source>Could not write the project for the atlas: %1</source>
        <translation>无法为图谱写入项目：%1</translation>
    </message>
    <message>
        <source>Computing in one process…</source>
        <translation>正在单进程中计算…</translation>
    </message>
    <message>
        <source>Starting the Dask cluster…</source>
        <translation>正在启动 Dask 集群…</translation>
    </message>
    <message>
        <source>Cancelling: the cluster&apos;s tasks are being cancelled…</source>
        <translation>正在取消：正在取消集群的任务…</translation>
    </message>
    <message>
        <source>Round 1: the grid&apos;s %1 points…</source>
        <translation>第 1 轮：网格的 %1 个点…</translation>
    </message>
    <message>
        <source>Round %1: %2 points where the class changes…</source>
        <translation>第 %1 轮：类发生变化处的 %2 个点…</translation>
    </message>
    <message>
        <source>Round %1: %2 of %3 points; %4 in all, %5 s</source>
        <translation>第 %1 轮：%2/%3 个点；共 %4 个，%5 秒</translation>
    </message>
    <message>
        <source>from %1 to %2</source>
        <translation>从 %1 到 %2</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s) in %1 round(s), %2 s on %3 worker(s) (%4).</source>
        <translation>
            <numerusform>%n 个点，%1 轮，%2 秒，%3 个工作进程（%4）。</numerusform>
        </translation>
    </message>
    <message>
        <source>Nowhere certified C^%1.</source>
        <translation>没有任何位置被证明为 C^%1。</translation>
    </message>
    <message>
        <source>C^%1 %2.</source>
        <translation>C^%1：%2。</translation>
    </message>
    <message>
        <source>The atlas gave no rows.</source>
        <translation>图谱未返回任何行。</translation>
    </message>
    <message>
        <source>Cancelled; the points computed so far are shown.</source>
        <translation>已取消；显示目前已计算的点。</translation>
    </message>
    <message>
        <source>could not start %1: %2</source>
        <translation>无法启动 %1：%2</translation>
    </message>
    <message>
        <source>exit code %1</source>
        <translation>退出代码 %1</translation>
    </message>
    <message>
        <source>The atlas failed: %1</source>
        <translation>图谱计算失败：%1</translation>
    </message>
    <message>
        <source>Add an item with %1</source>
        <translation>添加参数为 %1 的项</translation>
    </message>
    <message>
        <source>Added &quot;%1&quot; (Edit &gt; Undo removes it).</source>
        <translation>已添加“%1”（“编辑 &gt; 撤销”可将其移除）。</translation>
    </message>
    <message>
        <source>the scheme refuses these parameters</source>
        <translation>该格式不接受这些参数</translation>
    </message>
    <message>
        <source>No item added: %1</source>
        <translation>未添加任何项：%1</translation>
    </message>
</context>
<context>
    <name>awb::RegularityCertificate</name>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 不是有限数</translation>
    </message>
    <message>
        <source>%1 is not an index</source>
        <translation>%1 不是索引</translation>
    </message>
    <message>
        <source>%1 has no array &quot;%2&quot;</source>
        <translation>%1 没有数组 &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1 is not an array of numbers</source>
        <translation>%1 不是数值数组</translation>
    </message>
    <message>
        <source>&quot;polytope&quot; is not an awb-invariant-polytope object</source>
        <translation>&quot;polytope&quot; 不是 awb-invariant-polytope 对象</translation>
    </message>
    <message>
        <source>polytope.matrices[%1] is not square</source>
        <translation>polytope.matrices[%1] 不是方阵</translation>
    </message>
    <message>
        <source>polytope.lambda[%1] holds a term that is not [index, coefficient]</source>
        <translation>polytope.lambda[%1] 含有一个不是 [index, coefficient] 形式的项</translation>
    </message>
    <message>
        <source>the regularity is not exact: no invariant polytope closed, so there is no certificate (%1)</source>
        <translation>正则性不是精确的：没有不变多面体闭合，因此没有证书（%1）</translation>
    </message>
    <message>
        <source>not JSON: %1 at offset %2</source>
        <translation>不是 JSON：%1，位于偏移量 %2 处</translation>
    </message>
    <message>
        <source>not an attractor-workbench regularity certificate (format %1, version 1)</source>
        <translation>不是 attractor-workbench 正则性证书（格式 %1，版本 1）</translation>
    </message>
    <message>
        <source>the scheme has no difference scheme to certify: %1</source>
        <translation>该格式没有可供认证的差分格式：%1</translation>
    </message>
    <message>
        <source>the certificate has %1 matrices, the scheme&apos;s analysis %2</source>
        <translation>证书包含 %1 个矩阵，而该格式的分析给出 %2 个</translation>
    </message>
    <message>
        <source>matrix %1 of the certificate is not the scheme&apos;s (the transition matrix T_%2 of its difference scheme)</source>
        <translation>证书的矩阵 %1 与该格式的不符（应为其差分格式的转移矩阵 T_%2）</translation>
    </message>
    <message>
        <source>arity %1 and shift %2 do not match the scheme&apos;s (%3 and %4)</source>
        <translation>元数 %1 和平移量 %2 与该格式的（%3 和 %4）不一致</translation>
    </message>
    <message>
        <source>the claimed Hölder exponent [%1, %2] is not what the polytope proves: [%3, %4]</source>
        <translation>声称的 Hölder 指数 [%1, %2] 与多面体所证明的不符：[%3, %4]</translation>
    </message>
    <message>
        <source>certificate verified: the Hölder exponent of the %1 lies in [%2, %3]; JSR in [%4, %5]</source>
        <translation>证书已验证：%1 的 Hölder 指数位于 [%2, %3] 内；JSR 位于 [%4, %5] 内</translation>
    </message>
    <message>
        <source>certificate rejected: %1</source>
        <translation>证书被拒绝：%1</translation>
    </message>
</context>
<context>
    <name>awb::RegularityChart</name>
    <message>
        <source>Regularity of the four-point scheme</source>
        <translation>四点格式的正则性</translation>
    </message>
    <message>
        <source>Certified Hölder regularity r(ω) of the four-point scheme</source>
        <translation>四点格式经验证的 Hölder 正则性 r(ω)</translation>
    </message>
    <message>
        <source>lower bound</source>
        <translation>下界</translation>
    </message>
    <message>
        <source>upper bound</source>
        <translation>上界</translation>
    </message>
    <message>
        <source>known: ω = 0 → 1, ω = 1/16 → 2</source>
        <translation type="vanished">已知：ω = 0 → 1，ω = 1/16 → 2</translation>
    </message>
    <message>
        <source>tension ω</source>
        <translation>张力参数 ω</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Computing %1 values of ω…</source>
        <translation>正在计算 ω 的 %1 个值…</translation>
    </message>
    <message>
        <source>%1 values of ω; widest interval %2 (bounds certified; the upper bound is exact for this interpolatory scheme)</source>
        <translation type="vanished">ω 的 %1 个值；最宽区间为 %2（界经过验证；对于此插值格式，上界是精确的）</translation>
    </message>
    <message>
        <source>regularity r</source>
        <translation>正则性 r</translation>
    </message>
    <message>
        <source>r(0) = 1, r(1/16) = 2</source>
        <translation>r(0) = 1, r(1/16) = 2</translation>
    </message>
    <message>
        <source>C%1 (certified)</source>
        <translation>C%1（已认证）</translation>
    </message>
    <message>
        <source>; C¹ for ω in (%1, %2), the ends in [%3, %4] and [%5, %6]</source>
        <translation>；当 ω ∈ (%1, %2) 时为 C¹，两端分别位于 [%3, %4] 和 [%5, %6] 内</translation>
    </message>
    <message>
        <source>%1 values of ω; widest interval %2 (bounds certified; the upper bound is exact for this interpolatory scheme)%3</source>
        <translation>%1 个 ω 值；最宽区间 %2（界已认证；对于此插值格式，上界是精确的）%3</translation>
    </message>
</context>
<context>
    <name>awb::RegularityPanel</name>
    <message>
        <source>Regularity: no curve scheme</source>
        <translation>正则性：无曲线细分格式</translation>
    </message>
    <message>
        <source>Regularity %p%</source>
        <translation>正则性 %p%</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop the regularity analysis; the bounds reached so far stay</source>
        <translation>停止正则性分析；保留目前已得到的界</translation>
    </message>
    <message>
        <source>Regularity of %1: computing…</source>
        <translation>%1 的正则性：正在计算…</translation>
    </message>
    <message>
        <source>so far: r in [%1, %2]</source>
        <translation>目前：r ∈ [%1, %2]</translation>
    </message>
    <message>
        <source>Regularity: %1</source>
        <translation>正则性：%1</translation>
    </message>
    <message>
        <source>Save Certificate…</source>
        <translation>保存证书…</translation>
    </message>
    <message>
        <source>The invariant polytope that proves the exponent, as JSON: attractor-cli verify-regularity re-checks it without any search</source>
        <translation>证明该指数的不变多面体，以 JSON 格式保存：attractor-cli verify-regularity 无需任何搜索即可重新检验它</translation>
    </message>
</context>
<context>
    <name>awb::RemoveControlPointCommand</name>
    <message>
        <source>Remove a control point of %1</source>
        <translation>移除 %1 的一个控制点</translation>
    </message>
</context>
<context>
    <name>awb::RemoveItemCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>移除 %1</translation>
    </message>
</context>
<context>
    <name>awb::SchemeFamily</name>
    <message>
        <source>a family has one or two parameters, got %1</source>
        <translation>格式族应有一个或两个参数，实际为 %1</translation>
    </message>
    <message>
        <source>the two parameters have the same name &apos;%1&apos;</source>
        <translation>两个参数同名“%1”</translation>
    </message>
    <message>
        <source>a mask with parameters needs a mask item; this one is %1</source>
        <translation>带参数的掩模需要一个掩模项；此项为 %1</translation>
    </message>
    <message>
        <source>the parameter of a mask must be a name that is not a function or constant (pi, e, sqrt, ...), got &apos;%1&apos;</source>
        <translation>掩模的参数必须是一个既非函数也非常数（pi, e, sqrt, ...）的名称，实际为“%1”</translation>
    </message>
    <message>
        <source>the mask &apos;%1&apos; does not contain the parameter &apos;%2&apos;</source>
        <translation>掩模“%1”不包含参数“%2”</translation>
    </message>
    <message>
        <source>the scheme (%1) has no parameter &apos;%2&apos;: omega belongs to the four-point scheme, a and b to corner cutting; a mask item takes a mask with the parameter in its coefficients</source>
        <translation>格式（%1）没有参数“%2”：omega 属于四点格式，a 和 b 属于割角格式；掩模项接受系数中含有该参数的掩模</translation>
    </message>
    <message>
        <source>expected %1 parameter values, got %2</source>
        <translation>应有 %1 个参数值，实际为 %2 个</translation>
    </message>
    <message>
        <source>expected a list of names</source>
        <translation>应为名称列表</translation>
    </message>
    <message>
        <source>family: %1: %2</source>
        <translation>格式族：%1：%2</translation>
    </message>
    <message>
        <source>an atlas row has no value of &apos;%1&apos;</source>
        <translation>图谱的某一行没有“%1”的值</translation>
    </message>
</context>
<context>
    <name>awb::SchemeRegularity</name>
    <message>
        <source>does not apply: a complex de Casteljau parameter is not a real subdivision scheme</source>
        <translation>不适用：复 de Casteljau 参数不是实细分格式</translation>
    </message>
    <message>
        <source>does not apply: %1</source>
        <translation>不适用：%1</translation>
    </message>
</context>
<context>
    <name>awb::ScriptRecorder</name>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>编辑</translation>
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
        <translation>单位圆</translation>
    </message>
    <message>
        <source>dominant 1</source>
        <translation>占优特征值 1</translation>
    </message>
    <message>
        <source>subdominant</source>
        <translation>次占优特征值</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: λ = %2, |λ| = %3, multiplicity %4, arg λ = %6° (map %5)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;：λ = %2，|λ| = %3，重数 %4，arg λ = %6°（映射 %5）</translation>
    </message>
    <message>
        <source> — dominant</source>
        <translation> — 占优</translation>
    </message>
    <message>
        <source> — subdominant</source>
        <translation> — 次占优</translation>
    </message>
    <message>
        <source>&lt;p&gt;No maps.&lt;/p&gt;</source>
        <translation>&lt;p&gt;没有映射。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;All maps are (eventually) contractive&lt;/b&gt;: the IFS has a unique attractor.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;所有映射都是（最终）压缩的&lt;/b&gt;：该 IFS 有唯一的吸引子。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;%1 is not contractive&lt;/b&gt;: the IFS has no attractor and its iteration does not converge.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;%1 不是压缩的&lt;/b&gt;：该 IFS 没有吸引子，其迭代不收敛。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Not contractive: spectral radius %1 ≥ 1.</source>
        <translation>非压缩：谱半径 %1 ≥ 1。</translation>
    </message>
    <message>
        <source>Contractive: ‖A‖&lt;sub&gt;2&lt;/sub&gt; = %1 &amp;lt; 1.</source>
        <translation>压缩：‖A‖&lt;sub&gt;2&lt;/sub&gt; = %1 &amp;lt; 1。</translation>
    </message>
    <message>
        <source>Eventually contractive: spectral radius %1 &amp;lt; 1, ‖A&lt;sup&gt;%2&lt;/sup&gt;‖&lt;sub&gt;2&lt;/sub&gt; &amp;lt; 1.</source>
        <translation>最终压缩：谱半径 %1 &amp;lt; 1，‖A&lt;sup&gt;%2&lt;/sup&gt;‖&lt;sub&gt;2&lt;/sub&gt; &amp;lt; 1。</translation>
    </message>
    <message>
        <source>Eventually contractive: spectral radius %1 &amp;lt; 1.</source>
        <translation>最终压缩：谱半径 %1 &amp;lt; 1。</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>No subdominant eigenvalue: the map is constant.</source>
        <translation>没有次占优特征值：该映射是常值映射。</translation>
    </message>
    <message>
        <source>real positive</source>
        <translation>正实数</translation>
    </message>
    <message>
        <source>The curve has a half-tangent at the fixed point, along the eigenvector (G¹ where the two sides&apos; eigenvectors align).</source>
        <translation>曲线在不动点处沿特征向量方向有单侧切线（两侧特征向量方向一致时为 G¹）。</translation>
    </message>
    <message>
        <source>Repeated: the tangent direction at the fixed point depends on the control points.</source>
        <translation>重特征值：不动点处的切线方向取决于控制点。</translation>
    </message>
    <message>
        <source>real negative</source>
        <translation>负实数</translation>
    </message>
    <message>
        <source>The curve oscillates at the fixed point and has no tangent there.</source>
        <translation>曲线在不动点处振荡，该处没有切线。</translation>
    </message>
    <message>
        <source>complex pair</source>
        <translation>共轭复数对</translation>
    </message>
    <message>
        <source>The curve spirals around the fixed point (no tangent).</source>
        <translation>曲线绕不动点螺旋（没有切线）。</translation>
    </message>
    <message>
        <source>complex</source>
        <translation>复数</translation>
    </message>
    <message>
        <source>Near the fixed point the map acts as the spiral similarity z ↦ λz: the curve spirals around the fixed point (no tangent).</source>
        <translation>在不动点附近，该映射作用为螺旋相似变换 z ↦ λz：曲线绕不动点螺旋（没有切线）。</translation>
    </message>
    <message>
        <source>mixed</source>
        <translation>混合</translation>
    </message>
    <message>
        <source>Several eigenvalues of the same modulus with different signs or phases: no single tangent behaviour.</source>
        <translation>存在若干模相同但符号或相位不同的特征值：没有单一的切线行为。</translation>
    </message>
    <message>
        <source>Subdominant: none.</source>
        <translation>次占优：无。</translation>
    </message>
    <message>
        <source>Subdominant: %1 (%2, |λ| = %3, multiplicity %4).</source>
        <translation>次占优：%1（%2，|λ| = %3，重数 %4）。</translation>
    </message>
    <message>
        <source>Unknown file type “%1”: use .pdf, .svg or .png.</source>
        <translation>未知的文件类型“%1”：请使用 .pdf、.svg 或 .png。</translation>
    </message>
    <message>
        <source>Eigenvalues</source>
        <translation>特征值</translation>
    </message>
    <message>
        <source>%1: λ = %2</source>
        <translation>%1：λ = %2</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;%1 is not contractive, but the IFS contracts on average&lt;/b&gt;: its Lyapunov exponent is %2 &amp;lt; 0 (Barnsley–Elton), so random iteration converges to its attractor, as in flame renderers; deterministic iteration does not.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;%1 不是压缩的，但该 IFS 平均压缩&lt;/b&gt;：其李雅普诺夫指数为 %2 &amp;lt; 0（Barnsley–Elton），因此随机迭代收敛到其吸引子，正如火焰分形渲染器那样；确定性迭代则不收敛。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>The spectra below are those of the xforms&apos; affine (pre) maps; the variations bend the maps, so the spectra alone say nothing of the flame&apos;s attractor.</source>
        <translation>下面的谱是各 xform 仿射（前置）映射的谱；变体使映射弯曲，因此仅凭这些谱无法说明火焰的吸引子。</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;The flame contracts on average&lt;/b&gt;: the top Lyapunov exponent of its chaos game along its own orbit is %1 &amp;lt; 0, so the game converges to its attractor. %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;火焰平均意义下收缩&lt;/b&gt;：其混沌游戏沿自身轨道的最大 Lyapunov 指数为 %1 &amp;lt; 0，因此游戏收敛到其吸引子。%2&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;The flame does not contract on average&lt;/b&gt;: the top Lyapunov exponent of its chaos game along its own orbit is %1 &amp;ge; 0, so its picture is not an attractor&apos;s. %2&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b01e1e&apos;&gt;&lt;b&gt;火焰平均意义下不收缩&lt;/b&gt;：其混沌游戏沿自身轨道的最大 Lyapunov 指数为 %1 &amp;ge; 0，因此其图像不是吸引子的图像。%2&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>awb::StartSetSpec</name>
    <message>
        <source>a lifted start set needs at least one point</source>
        <translation>提升初始集至少需要一个点</translation>
    </message>
    <message>
        <source>lifted start point %1 has %2 coordinates: every point needs the same number, at least 2</source>
        <translation>提升初始点 %1 有 %2 个坐标：每个点的坐标数必须相同，且至少为 2</translation>
    </message>
    <message>
        <source>every point must have finite coordinates</source>
        <translation>每个点的坐标都必须是有限数</translation>
    </message>
    <message>
        <source>a start set of kind &quot;%1&quot; needs exactly %2 points, got %3</source>
        <translation>类型为 &quot;%1&quot; 的初始集恰好需要 %2 个点，实际为 %3 个</translation>
    </message>
    <message>
        <source>a start set of kind &quot;%1&quot; needs at least %2 points, got %3</source>
        <translation>类型为 &quot;%1&quot; 的初始集至少需要 %2 个点，实际为 %3 个</translation>
    </message>
    <message>
        <source>a start set of net points needs at least one index</source>
        <translation>网格点初始集至少需要一个索引</translation>
    </message>
    <message>
        <source>a start set of net points takes at most %1 indices, got %2</source>
        <translation>网格点初始集最多 %1 个索引，得到 %2 个</translation>
    </message>
    <message>
        <source>net point %1 of the start set has the index %2: indices count from 0</source>
        <translation>初始集的第 %1 个网格点索引为 %2：索引从 0 开始</translation>
    </message>
</context>
<context>
    <name>awb::StartSetText</name>
    <message>
        <source>&apos;%1&apos; is not a finite number</source>
        <translation>“%1”不是有限数</translation>
    </message>
    <message>
        <source>a start set is written point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | vertex-limits, got &apos;%1&apos;</source>
        <translation type="vanished">初始集的写法为 point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | vertex-limits，得到的是“%1”</translation>
    </message>
    <message>
        <source>a %1 needs %2 coordinates (%3 per point), got %4</source>
        <translation>%1 需要 %2 个坐标（每点 %3 个），得到 %4 个</translation>
    </message>
    <message>
        <source>a multiple of %1</source>
        <translation>%1 的倍数</translation>
    </message>
    <message>
        <source>lifted: needs at least one point</source>
        <translation>lifted: 至少需要一个点</translation>
    </message>
    <message>
        <source>vertex-limits needs a mesh item; &apos;%1&apos; is a %2</source>
        <translation>vertex-limits 需要网格对象；“%1”是%2</translation>
    </message>
    <message>
        <source>a start set is written point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | net:i,j,... | vertex-limits, got &apos;%1&apos;</source>
        <translation>初始集的写法为 point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;... | net:i,j,... | vertex-limits，得到的是“%1”</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a net point index (an integer from 0)</source>
        <translation>“%1”不是网格点索引（从 0 开始的整数）</translation>
    </message>
    <message>
        <source>net: needs at least one index</source>
        <translation>net: 至少需要一个索引</translation>
    </message>
</context>
<context>
    <name>awb::StyleSpec</name>
    <message>
        <source>the density gamma must be between 0.2 and 10, got %1</source>
        <translation>密度 gamma 必须介于 0.2 和 10 之间，实际为 %1</translation>
    </message>
    <message>
        <source>the address prefix length must be between 1 and %1, got %2</source>
        <translation>地址前缀长度必须介于 1 和 %1 之间，实际为 %2</translation>
    </message>
    <message>
        <source>the point size must be more than 0 and at most %1 pixels</source>
        <translation>点大小必须大于 0 且不超过 %1 像素</translation>
    </message>
    <message>
        <source>colour %1 is &quot;%2&quot;, expected &quot;#rrggbb&quot; (lower-case hexadecimal)</source>
        <translation>颜色 %1 为 &quot;%2&quot;，应为 &quot;#rrggbb&quot;（小写十六进制）</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionCurveItem</name>
    <message>
        <source>Bézier of degree %1 needs exactly %2 control points, got %3</source>
        <translation>%1 次 Bézier 曲线恰好需要 %2 个控制点，实际为 %3 个</translation>
    </message>
    <message>
        <source>a complex Bézier parameter has no real scheme</source>
        <translation>复 Bézier 参数没有对应的实细分格式</translation>
    </message>
    <message>
        <source>unknown scheme kind</source>
        <translation>未知的细分格式类型</translation>
    </message>
    <message>
        <source>the complex parameter t = %1 %2 %3i must satisfy |t| &lt; 1 and |1 - t| &lt; 1 (004 §3.7)</source>
        <translation>复参数 t = %1 %2 %3i 必须满足 |t| &lt; 1 且 |1 - t| &lt; 1（004 §3.7）</translation>
    </message>
    <message>
        <source>Curve</source>
        <translation>曲线</translation>
    </message>
    <message>
        <source>Change scheme of %1</source>
        <translation>更改 %1 的细分格式</translation>
    </message>
    <message>
        <source>expected [re, im] or a number</source>
        <translation>应为 [re, im] 或一个数</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>细分格式</translation>
    </message>
    <message>
        <source>Uniform B-spline</source>
        <translation>均匀 B 样条</translation>
    </message>
    <message>
        <source>End-interpolating B-spline</source>
        <translation>端点插值 B 样条</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Corner cutting</source>
        <translation>割角</translation>
    </message>
    <message>
        <source>Four-point</source>
        <translation>四点格式</translation>
    </message>
    <message>
        <source>Bézier (de Casteljau)</source>
        <translation>Bézier（de Casteljau）</translation>
    </message>
    <message>
        <source>Own matrices</source>
        <translation>自定义矩阵</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>次数</translation>
    </message>
    <message>
        <source>Degree n: the curve has n + 1 control points</source>
        <translation>次数 n：曲线有 n + 1 个控制点</translation>
    </message>
    <message>
        <source>Degree of the B-spline (Lane–Riesenfeld, 004 eq. 2.7)</source>
        <translation>B 样条的次数（Lane–Riesenfeld，004 eq. 2.7）</translation>
    </message>
    <message>
        <source>Split parameter t</source>
        <translation>分割参数 t</translation>
    </message>
    <message>
        <source>de Casteljau split at t (004 eq. 2.5). A complex t inside both discs |t| &lt; 1, |1 − t| &lt; 1 gives a fractal curve (004 §3.7).</source>
        <translation>在 t 处做 de Casteljau 分割（004 eq. 2.5）。若复数 t 位于两个圆盘 |t| &lt; 1、|1 − t| &lt; 1 的内部，则得到分形曲线（004 §3.7）。</translation>
    </message>
    <message>
        <source>Tension ω</source>
        <translation>张力参数 ω</translation>
    </message>
    <message>
        <source>1/16 gives C1 curves reproducing cubics; −1/2 &lt; ω &lt; 0 or 1/4 ≤ ω &lt; 1/2 gives fractal curves (004 Thm. 2.4.1)</source>
        <translation>ω = 1/16 给出再生三次多项式的 C1 曲线；−1/2 &lt; ω &lt; 0 或 1/4 ≤ ω &lt; 1/2 给出分形曲线（004 Thm. 2.4.1）</translation>
    </message>
    <message>
        <source>New points at parameters a &lt; b on every edge (Chaikin: 1/4, 3/4)</source>
        <translation>在每条边的参数 a &lt; b 处生成新点（Chaikin：1/4, 3/4）</translation>
    </message>
    <message>
        <source>First cut a</source>
        <translation>第一个割点 a</translation>
    </message>
    <message>
        <source>Second cut b</source>
        <translation>第二个割点 b</translation>
    </message>
    <message>
        <source>Subdivision curve</source>
        <translation>细分曲线</translation>
    </message>
    <message>
        <source>mask entry %1, &quot;%2&quot;, is not a number (fractions such as 3/8 and expressions such as (1 + sqrt(3))/8 are)</source>
        <translation>掩模第 %1 项 &quot;%2&quot; 不是数字（可以是分数，如 3/8，或表达式，如 (1 + sqrt(3))/8）</translation>
    </message>
    <message>
        <source>no sum rule: σ(z) = %1 does not divide the symbol a(z), so the scheme has no difference scheme and cannot converge</source>
        <translation>无和规则：σ(z) = %1 不整除符号 a(z)，因此该格式没有差分格式，不能收敛</translation>
    </message>
    <message>
        <source>1 sum rule</source>
        <translation>1 条和规则</translation>
    </message>
    <message>
        <source>%1 sum rules</source>
        <translation>%1 条和规则</translation>
    </message>
    <message>
        <source>%1: a(z) = σ(z)%2 b(z) / %3%2 with σ(z) = %4 and b = (%5) from z%6</source>
        <translation>%1：a(z) = σ(z)%2 b(z) / %3%2，其中 σ(z) = %4，b = (%5) 从 z%6 起</translation>
    </message>
    <message>
        <source>expected a non-empty array of coefficients</source>
        <translation>应为非空的系数数组</translation>
    </message>
    <message>
        <source>Mask</source>
        <translation>掩模</translation>
    </message>
    <message>
        <source>Arity N</source>
        <translation>元数 N</translation>
    </message>
    <message>
        <source>Each step makes N new points per old one. A new arity whose cosets the mask does not fit starts from the N-ary piecewise linear mask.</source>
        <translation>每一步对每个旧点生成 N 个新点。若当前掩模不适合新元数的陪集，则从 N 进分段线性掩模开始。</translation>
    </message>
    <message>
        <source>Mask a_k</source>
        <translation>掩模 a_k</translation>
    </message>
    <message>
        <source>q_n = Σ a_(n − N l) p_l. Separate the coefficients by commas (by semicolons to use decimal commas); fractions (3/8) and expressions ((1 + sqrt(3))/8) are kept as typed. Each of the N cosets a_(r + N k) must sum to 1.</source>
        <translation>q_n = Σ a_(n − N l) p_l。系数之间用逗号分隔（若使用小数逗号，则用分号分隔）；分数（3/8）和表达式（(1 + sqrt(3))/8）按输入原样保留。N 个陪集 a_(r + N k) 各自之和必须为 1。</translation>
    </message>
    <message>
        <source>First index k</source>
        <translation>起始索引 k</translation>
    </message>
    <message>
        <source>The index of the mask&apos;s first coefficient: the cubic B-spline is 1/8, 1/2, 3/4, 1/2, 1/8 from k = −2</source>
        <translation>掩模首个系数的索引：三次 B 样条为 1/8, 1/2, 3/4, 1/2, 1/8，从 k = −2 开始</translation>
    </message>
    <message>
        <source>Symbol</source>
        <translation>符号</translation>
    </message>
    <message>
        <source>The symbol a(z) = Σ a_k z^k divided by σ(z) = 1 + z + … + z^(N−1) as often as it goes: each factor is one sum rule (polynomials of one more degree reproduced, one more difference scheme)</source>
        <translation>符号 a(z) = Σ a_k z^k 被 σ(z) = 1 + z + … + z^(N−1) 尽可能多次地整除：每个因子对应一条和规则（可再现的多项式次数高一次，差分格式多一个）</translation>
    </message>
    <message>
        <source>the symbol follows from the mask: edit the mask</source>
        <translation type="vanished">符号由掩模决定：请编辑掩模</translation>
    </message>
    <message>
        <source>Matrices S_i</source>
        <translation>矩阵 S_i</translation>
    </message>
    <message>
        <source>The subdivision matrices S_1 .. S_p, m x m with rows summing to 1; edited cell by cell in the Matrices dock</source>
        <translation>细分矩阵 S_1 .. S_p，大小为 m x m，每行之和为 1；在“矩阵”面板中逐个单元格编辑</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionMeshItem</name>
    <message>
        <source>Mesh surface</source>
        <translation>网格曲面</translation>
    </message>
    <message>
        <source>Change mesh of %1</source>
        <translation>更改 %1 的网格</translation>
    </message>
    <message>
        <source>a mesh surface is drawn by deterministic iteration: random iteration of its pieces is not implemented</source>
        <translation>网格曲面通过确定性迭代绘制：尚未实现对其曲面片的随机迭代</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after %3 isolating steps (docs/mathematics.md, &quot;Extraordinary vertices&quot;)</source>
        <translation type="vanished">经过 %3 步隔离后共有 %1 个曲面片，分属 %2 种类型（docs/mathematics.md，&quot;Extraordinary vertices&quot;）</translation>
    </message>
    <message>
        <source>expected an array of faces, each an array of vertex numbers</source>
        <translation>应为由面组成的数组，每个面是顶点编号的数组</translation>
    </message>
    <message>
        <source>expected a face: an array of vertex numbers (0-based)</source>
        <translation>应为面：顶点编号的数组（从 0 开始）</translation>
    </message>
    <message>
        <source>vertex numbers are whole numbers (0-based)</source>
        <translation>顶点编号必须是整数（从 0 开始）</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>细分格式</translation>
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
        <translation>Loop 只接受三角形网格</translation>
    </message>
    <message>
        <source>Colours</source>
        <translation type="vanished">颜色</translation>
    </message>
    <message>
        <source>By map</source>
        <translation>按映射</translation>
    </message>
    <message>
        <source>By level around extraordinary vertices</source>
        <translation>按奇异顶点周围的层级</translation>
    </message>
    <message>
        <source>Style</source>
        <translation>样式</translation>
    </message>
    <message>
        <source>a mesh has no single lifted space: each of its pieces is lifted over its own control net</source>
        <translation>网格没有单一的提升空间：它的每个曲面片都在其自身的控制网格上提升</translation>
    </message>
    <message>
        <source>By level: around an extraordinary vertex, the rings C, f(C), f²(C), … of its IFS with condensation get colours in turn</source>
        <translation>按层级：在奇异顶点周围，其带凝聚集的 IFS 的环 C、f(C)、f²(C)、… 依次着色</translation>
    </message>
    <message>
        <source>the steps before the limit positions must be 0 to %1, got %2</source>
        <translation>极限位置之前的步数必须为 0 到 %1，得到 %2</translation>
    </message>
    <message>
        <source>%1 steps give about %2 vertices: more than %3</source>
        <translation>%1 步将产生约 %2 个顶点：超过 %3</translation>
    </message>
    <message>
        <source>Attractor Workbench: item %1, %2 after %3 steps, every vertex at its limit position</source>
        <translation>Attractor Workbench：对象 %1，%2 细分 %3 步后，每个顶点都位于其极限位置</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>顶点</translation>
    </message>
    <message>
        <source>The mesh&apos;s vertices [x, y, z]: its control points</source>
        <translation>网格的顶点 [x, y, z]：即其控制点</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>面</translation>
    </message>
    <message>
        <source>Each face as the loop of its vertex numbers (0-based)</source>
        <translation>每个面表示为由其顶点编号构成的环（从 0 开始）</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after %3 steps that isolate the extraordinary vertices</source>
        <translation>经过 %3 步隔离奇异顶点的细分后，共有 %1 个曲面片，分属 %2 种类型</translation>
    </message>
    <message>
        <source>%1 pieces of %2 kinds after one step that isolates the extraordinary vertices</source>
        <translation>经过一步隔离奇异顶点的细分后，共有 %1 个曲面片，分属 %2 种类型</translation>
    </message>
    <message>
        <source>Pieces coloured</source>
        <translation>曲面片着色</translation>
    </message>
    <message>
        <source>expected an array, each entry %1</source>
        <translation>应为数组，每个条目为%1</translation>
    </message>
    <message>
        <source>expected %1</source>
        <translation>应为%1</translation>
    </message>
    <message>
        <source>vertex and face numbers are whole numbers (0-based)</source>
        <translation>顶点和面的编号必须是整数（从 0 开始）</translation>
    </message>
    <message>
        <source>a sharpness is a number of 0 or more (10 or more: infinitely sharp)</source>
        <translation>锐度是大于或等于 0 的数（10 及以上：无限锐利）</translation>
    </message>
    <message>
        <source>a crease: [first vertex, second vertex, sharpness]</source>
        <translation>折痕，格式为 [第一个顶点, 第二个顶点, 锐度]</translation>
    </message>
    <message>
        <source>Creases</source>
        <translation>折痕</translation>
    </message>
    <message>
        <source>Sharp features</source>
        <translation>尖锐特征</translation>
    </message>
    <message>
        <source>Sharp edges as [first vertex, second vertex, sharpness]: sharp for that many levels (10 or more: for ever), as OpenSubdiv&apos;s creases</source>
        <translation>尖锐边，格式为 [第一个顶点, 第二个顶点, 锐度]：在相应层数内保持尖锐（10 及以上：始终尖锐），与 OpenSubdiv 的折痕（crease）相同</translation>
    </message>
    <message>
        <source>a corner: [vertex, sharpness]</source>
        <translation>角点，格式为 [顶点, 锐度]</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>角点</translation>
    </message>
    <message>
        <source>Sharp vertices as [vertex, sharpness]: the surface passes through them while the sharpness lasts</source>
        <translation>尖锐顶点，格式为 [顶点, 锐度]：在锐度持续期间，曲面经过这些顶点</translation>
    </message>
    <message>
        <source>a face number (0-based)</source>
        <translation>面编号（从 0 开始）</translation>
    </message>
    <message>
        <source>Holes</source>
        <translation>孔洞</translation>
    </message>
    <message>
        <source>Faces (0-based) left out of the surface; they still shape their neighbours</source>
        <translation>从曲面中略去的面（编号从 0 开始）；它们仍会影响相邻面的形状</translation>
    </message>
    <message>
        <source>None (faces at the boundary are left out)</source>
        <translation>无（略去边界上的面）</translation>
    </message>
    <message>
        <source>Edges</source>
        <translation>边</translation>
    </message>
    <message>
        <source>Edges and corners</source>
        <translation>边和角点</translation>
    </message>
    <message>
        <source>Boundary</source>
        <translation>边界</translation>
    </message>
    <message>
        <source>How the boundary is interpolated (OpenSubdiv&apos;s VtxBoundaryInterpolation): with corners, a vertex of one face is a corner of the surface</source>
        <translation>边界的插值方式（OpenSubdiv 的 VtxBoundaryInterpolation）：选择含角点时，只属于一个面的顶点成为曲面的角点</translation>
    </message>
    <message>
        <source>Uniform</source>
        <translation>均匀</translation>
    </message>
    <message>
        <source>Chaikin</source>
        <translation>Chaikin</translation>
    </message>
    <message>
        <source>Crease method</source>
        <translation>折痕方法</translation>
    </message>
    <message>
        <source>How a semi-sharp crease decays: by 1 per level, or Chaikin&apos;s average with its neighbours</source>
        <translation>半锐折痕的锐度如何衰减：每层减 1，或按 Chaikin 方法与相邻折痕取平均</translation>
    </message>
    <message>
        <source>Smooth triangles</source>
        <translation>平滑三角形</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>三角形</translation>
    </message>
    <message>
        <source>Catmull–Clark&apos;s edge points next to triangles: as for any face, or OpenSubdiv&apos;s smoother weights</source>
        <translation>Catmull–Clark 中与三角形相邻的边点：与其他任何面相同，或采用 OpenSubdiv 更平滑的权重</translation>
    </message>
    <message>
        <source>face %1: the mesh has %2 faces (0 to %3)</source>
        <translation>面 %1：网格有 %2 个面（0 到 %3）</translation>
    </message>
</context>
<context>
    <name>awb::SubdivisionSurfaceItem</name>
    <message>
        <source>Surface</source>
        <translation>曲面</translation>
    </message>
    <message>
        <source>Change net of %1</source>
        <translation>更改 %1 的控制网格</translation>
    </message>
    <message>
        <source>Change subdivision rounds of %1</source>
        <translation>更改 %1 的细分轮数</translation>
    </message>
    <message>
        <source>Turn the view of %1</source>
        <translation>旋转 %1 的视图</translation>
    </message>
    <message>
        <source>expected an array of lattice coordinates [i, j]</source>
        <translation>应为格点坐标 [i, j] 的数组</translation>
    </message>
    <message>
        <source>expected lattice coordinates [i, j]</source>
        <translation>应为格点坐标 [i, j]</translation>
    </message>
    <message>
        <source>lattice coordinates are whole numbers</source>
        <translation>格点坐标必须是整数</translation>
    </message>
    <message>
        <source>at least one map must be used (leave the field out to use all)</source>
        <translation>至少必须使用一个映射（省略该字段则使用全部映射）</translation>
    </message>
    <message>
        <source>map indices are whole numbers (0-based)</source>
        <translation>映射索引必须是整数（从 0 开始）</translation>
    </message>
    <message>
        <source>the elevation must be from -90 to 90 degrees</source>
        <translation>仰角必须在 -90 到 90 度之间</translation>
    </message>
    <message>
        <source>Scheme</source>
        <translation>细分格式</translation>
    </message>
    <message>
        <source>Bicubic B-spline (Catmull–Clark)</source>
        <translation>双三次 B 样条（Catmull–Clark）</translation>
    </message>
    <message>
        <source>Loop (three-direction box spline)</source>
        <translation>Loop（三向箱样条）</translation>
    </message>
    <message>
        <source>Kobbelt √3</source>
        <translation>Kobbelt √3</translation>
    </message>
    <message>
        <source>A new scheme starts from its own default net (000 §3)</source>
        <translation>新的细分格式从其自身的默认控制网格开始（000 §3）</translation>
    </message>
    <message>
        <source>Layout</source>
        <translation>布局</translation>
    </message>
    <message>
        <source>The patch&apos;s domain and the maps covering it</source>
        <translation>曲面片的定义域以及覆盖它的映射</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>映射</translation>
    </message>
    <message>
        <source>Map %1</source>
        <translation>映射 %1</translation>
    </message>
    <message>
        <source>Leave maps out to draw a fractal lying on the surface (000 Fig. 9)</source>
        <translation>省略部分映射可绘制位于曲面上的分形（000 Fig. 9）</translation>
    </message>
    <message>
        <source>View</source>
        <translation>视图</translation>
    </message>
    <message>
        <source>Azimuth</source>
        <translation>方位角</translation>
    </message>
    <message>
        <source>Direction of the orthographic camera around the z axis, in degrees</source>
        <translation>正交相机绕 z 轴的方向，单位为度</translation>
    </message>
    <message>
        <source>Elevation</source>
        <translation>仰角</translation>
    </message>
    <message>
        <source>Height of the camera above the xy plane, in degrees</source>
        <translation>相机相对 xy 平面的高度角，单位为度</translation>
    </message>
    <message>
        <source>Subdivision rounds</source>
        <translation>细分轮数</translation>
    </message>
    <message>
        <source>Rounds of classic subdivision of the net (000 Figs. 6–8, top)</source>
        <translation>对控制网格进行经典细分的轮数（000 Figs. 6–8，上排）</translation>
    </message>
    <message>
        <source>from 0 to %1 rounds</source>
        <translation>0 到 %1 轮</translation>
    </message>
    <message>
        <source>at least one map must stay on</source>
        <translation>至少必须保留一个映射</translation>
    </message>
    <message>
        <source>Subdivision surface</source>
        <translation>细分曲面</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>Lattice coordinates</source>
        <translation>格点坐标</translation>
    </message>
    <message>
        <source>Each control point&apos;s place [i, j] on the scheme&apos;s lattice</source>
        <translation>每个控制点在细分格式格点上的位置 [i, j]</translation>
    </message>
    <message>
        <source>Maps used</source>
        <translation>使用的映射</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceNet</name>
    <message>
        <source>every control point must have finite coordinates</source>
        <translation>每个控制点的坐标都必须是有限数</translation>
    </message>
    <message>
        <source>%1 lattice coordinates for %2 control points: give one [i, j] per control point</source>
        <translation>%2 个控制点对应 %1 个格点坐标：请为每个控制点给出一个 [i, j]</translation>
    </message>
    <message>
        <source>not the net of a %1 %2 patch: %3</source>
        <translation>不是 %1 %2 曲面片的控制网格：%3</translation>
    </message>
    <message>
        <source>map %1 does not exist: the %2 layout has maps 0 to %3</source>
        <translation>映射 %1 不存在：%2 布局的映射编号为 0 到 %3</translation>
    </message>
    <message>
        <source>list each map once, in increasing order (0-based)</source>
        <translation>每个映射只列出一次，按递增顺序（从 0 开始）</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceSchemeSpec</name>
    <message>
        <source>the %1 scheme has the layouts %2, not &apos;%3&apos;</source>
        <translation>%1 细分格式的布局为 %2，而不是“%3”</translation>
    </message>
</context>
<context>
    <name>awb::SurfaceView</name>
    <message>
        <source>Drawing… (CPU renderer)</source>
        <translation>正在绘制…（CPU 渲染器）</translation>
    </message>
    <message>
        <source>CPU renderer</source>
        <translation>CPU 渲染器</translation>
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
        <translation>深度 %1/%2（细节预算：%3 千个图元）· %4</translation>
    </message>
</context>
<context>
    <name>awb::UserGuideDialog</name>
    <message>
        <source>&lt;p&gt;The guide is missing.&lt;/p&gt;</source>
        <translation>&lt;p&gt;缺少用户指南。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Home or F</source>
        <translation>Home 或 F</translation>
    </message>
    <message>
        <source>Fit the attractor view to its content</source>
        <translation>使吸引子视图适应其内容</translation>
    </message>
    <message>
        <source>+ / −</source>
        <translation>+ / −</translation>
    </message>
    <message>
        <source>Zoom the attractor view in / out</source>
        <translation>放大/缩小吸引子视图</translation>
    </message>
    <message>
        <source>Mouse wheel</source>
        <translation>鼠标滚轮</translation>
    </message>
    <message>
        <source>Zoom at the cursor (view); scroll (panels)</source>
        <translation>在光标处缩放（视图）；滚动（面板）</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>用户指南</translation>
    </message>
</context>
<context>
    <name>awb::ValenceChart</name>
    <message>
        <source>Valences: choose a mesh surface</source>
        <translation>顶点价：请选择网格曲面</translation>
    </message>
    <message>
        <source>λ (subdominant)</source>
        <translation>λ（次占优）</translation>
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
        <translation>此网格</translation>
    </message>
    <message>
        <source>λ, μ, λ² against n (%1)</source>
        <translation>λ、μ、λ² 随 n 的变化（%1）</translation>
    </message>
    <message>
        <source>The subdominant eigenvalue λ, the next modulus μ and λ² of the local subdivision matrix at an interior vertex of valence n; the purple dots are this mesh&apos;s valences</source>
        <translation>价为 n 的内部顶点处局部细分矩阵的次占优特征值 λ、下一个模 μ 以及 λ²；紫色圆点为此网格中出现的价</translation>
    </message>
    <message>
        <source>valence n</source>
        <translation>价 n</translation>
    </message>
    <message>
        <source>μ = λ² (bounded curvature)</source>
        <translation>μ = λ²（曲率有界）</translation>
    </message>
    <message>
        <source>n = %1 … %2</source>
        <translation>n = %1 … %2</translation>
    </message>
    <message>
        <source>μ against λ²</source>
        <translation>μ 对 λ²</translation>
    </message>
    <message>
        <source>Below the diagonal (μ &lt; λ²) the curvature at the vertex is zero, on it bounded, above it unbounded (for generic data)</source>
        <translation>对角线下方（μ &lt; λ²）顶点处的曲率为零，对角线上有界，对角线上方无界（对一般数据）</translation>
    </message>
    <message>
        <source>μ</source>
        <translation>μ</translation>
    </message>
    <message>
        <source>λ, μ, λ² (%1)</source>
        <translation>λ、μ、λ²（%1）</translation>
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
        <translation type="vanished">为此顶点新建特征值图</translation>
    </message>
    <message>
        <source>Adds an eigenvalue plot item whose source is this extraordinary vertex: its local subdivision matrix&apos;s eigenvalues, kept in the project and printed with it</source>
        <translation>添加一个以此奇异顶点为来源的特征值图对象：其局部细分矩阵的特征值，保存在项目中并随项目一起打印</translation>
    </message>
    <message>
        <source>Click an extraordinary vertex (a purple diamond labelled with its valence) in the 3D view of a mesh surface: its spectrum, Reif&apos;s verdict and its characteristic map appear here.</source>
        <translation>在网格曲面的 3D 视图中单击一个奇异顶点（标有其价的紫色菱形）：其谱、Reif 判定结果和特征映射将显示在此处。</translation>
    </message>
    <message>
        <source>valence %1, %2, %3</source>
        <translation type="vanished">价 %1，%2，%3</translation>
    </message>
    <message>
        <source>on the boundary</source>
        <translation>位于边界</translation>
    </message>
    <message>
        <source>interior</source>
        <translation>内部</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the net of the vertex&apos;s piece).</source>
        <translation>局部细分矩阵 S：%1 × %1（该顶点所在曲面片的控制网格）。</translation>
    </message>
    <message>
        <source>Local subdivision matrix S: %1 × %1 (the vertex and every point within two faces of it).</source>
        <translation>局部细分矩阵 S：%1 × %1（该顶点及其周围两圈面内的所有点）。</translation>
    </message>
    <message>
        <source>λ₁ = 1, λ = %1, μ = %2, λ² = %3</source>
        <translation>λ₁ = 1，λ = %1，μ = %2，λ² = %3</translation>
    </message>
    <message>
        <source> (λ in closed form: %1)</source>
        <translation type="vanished">（λ 的闭式值：%1）</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for interior vertices only: a boundary vertex follows the crease rules, whose analysis needs the boundary&apos;s own characteristic map.</source>
        <translation type="vanished">此处仅对内部顶点判定 Reif 判据：边界顶点遵循折痕规则，其分析需要边界自身的特征映射。</translation>
    </message>
    <message>
        <source>spectral condition 1 &gt; λ₂ = λ₃ &gt; |λ₄|, λ real</source>
        <translation>谱条件 1 &gt; λ₂ = λ₃ &gt; |λ₄|，λ 为实数</translation>
    </message>
    <message>
        <source>characteristic map regular: the Jacobian keeps one sign on all %1 cells (signed areas %2 … %3)</source>
        <translation>特征映射正则：雅可比行列式在全部 %1 个单元上保持同号（有向面积 %2 … %3）</translation>
    </message>
    <message>
        <source>characteristic map not regular: signed areas from %1 to %2</source>
        <translation>特征映射非正则：有向面积从 %1 到 %2</translation>
    </message>
    <message>
        <source>characteristic map injective: its boundary winds %1 time(s) around the vertex</source>
        <translation>特征映射为单射：其边界绕顶点 %1 圈</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): the limit surface is C¹ at the vertex (for generic data).</source>
        <translation>判定（Reif 1995）：极限曲面在该顶点处为 C¹（对一般数据）。</translation>
    </message>
    <message>
        <source>Verdict (Reif 1995): C¹ is not established at the vertex.</source>
        <translation>判定（Reif 1995）：未能确认该顶点处为 C¹。</translation>
    </message>
    <message>
        <source>μ &lt; λ²: the curvature is zero at the vertex (the surface is flat there to second order, for generic data: no convex or saddle shape can be modelled at it)</source>
        <translation>μ &lt; λ²：顶点处的曲率为零（对一般数据，曲面在该处二阶平坦：无法在该处构造凸形或鞍形）</translation>
    </message>
    <message>
        <source>μ = λ²: the curvature is bounded at the vertex</source>
        <translation>μ = λ²：顶点处的曲率有界</translation>
    </message>
    <message>
        <source>μ &gt; λ²: the curvature is unbounded at the vertex (for generic data)</source>
        <translation>μ &gt; λ²：顶点处的曲率无界（对一般数据）</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3), normal (%4, %5, %6).</source>
        <translation>极限位置 (%1, %2, %3)，法向量 (%4, %5, %6)。</translation>
    </message>
    <message>
        <source>New Eigenvalue Plot</source>
        <translation>新建特征值图</translation>
    </message>
    <message>
        <source>; in closed form λ = %1 = %2</source>
        <translation>; 闭式为 λ = %1 = %2</translation>
    </message>
    <message>
        <source>No spectrum: %1.</source>
        <translation>无谱：%1。</translation>
    </message>
    <message>
        <source>Limit position (%1, %2, %3).</source>
        <translation>极限位置 (%1, %2, %3)。</translation>
    </message>
    <message>
        <source>a dart (one sharp edge ends here)</source>
        <translation>飞镖点（一条尖锐边在此终止）</translation>
    </message>
    <message>
        <source>on a crease</source>
        <translation>位于折痕上</translation>
    </message>
    <message>
        <source>a corner</source>
        <translation>角点</translation>
    </message>
    <message>
        <source>smooth</source>
        <translation>光滑</translation>
    </message>
    <message>
        <source>valence %1, %2, %3, %4</source>
        <translation>价 %1，%2，%3，%4</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided here for smooth interior vertices only: a boundary vertex or a sharp feature follows the crease rules, whose analysis needs the half-ring&apos;s own characteristic map.</source>
        <translation type="vanished">此处仅对光滑的内部顶点判定 Reif 判据：边界顶点或尖锐特征遵循折痕规则，其分析需要半环自身的特征映射。</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion sector by sector (Zorin 2000): each run of faces between sharp edges, with the eigenvalues whose eigenvectors do not vanish on it, on the canonical star of this neighbourhood:</source>
        <translation>逐扇区的 Reif 判据（Zorin 2000）：尖锐边之间的每一段面，取其特征向量在其上不为零的特征值，在该邻域的标准星形上计算：</translation>
    </message>
    <message>
        <source>face %1</source>
        <translation>面 %1</translation>
    </message>
    <message>
        <source>faces %1–%2</source>
        <translation>面 %1–%2</translation>
    </message>
    <message>
        <source>%1: λ₁ = %2, λ₂ = %3, μ = %4</source>
        <translation>%1：λ₁ = %2，λ₂ = %3，μ = %4</translation>
    </message>
    <message>
        <source>; C¹, curvature %1</source>
        <translation>；C¹，曲率%1</translation>
    </message>
    <message>
        <source>; not C¹: %1</source>
        <translation>；非 C¹：%1</translation>
    </message>
    <message>
        <source>; %1</source>
        <translation>；%1</translation>
    </message>
    <message>
        <source>Verdict: the limit surface is C¹ on every sector up to the creases (for generic data).</source>
        <translation>结论：极限曲面在每个扇区上直到折痕处都是 C¹ 的（对一般数据）。</translation>
    </message>
    <message>
        <source>Verdict: C¹ is not established on every sector.</source>
        <translation>结论：并非每个扇区都确立了 C¹。</translation>
    </message>
    <message>
        <source>Reif&apos;s criterion is decided for valences 3 to 64: this vertex is outside them.</source>
        <translation>Reif 判据仅对价 3 到 64 判定：该顶点不在此范围内。</translation>
    </message>
    <message>
        <source>zero (μ &lt; λ₂²)</source>
        <translation>为零（μ &lt; λ₂²）</translation>
    </message>
    <message>
        <source>bounded (μ = λ₂²)</source>
        <translation>有界（μ = λ₂²）</translation>
    </message>
    <message>
        <source>unbounded (μ &gt; λ₂²)</source>
        <translation>无界（μ &gt; λ₂²）</translation>
    </message>
</context>
<context>
    <name>awb::analysis</name>
    <message>
        <source>cannot index an empty point set</source>
        <translation>无法为空点集建立索引</translation>
    </message>
    <message>
        <source>point sets must have 1 to 3 coordinates</source>
        <translation>点集必须有 1 到 3 个坐标</translation>
    </message>
    <message>
        <source>point set</source>
        <translation>点集</translation>
    </message>
    <message>
        <source>point sets of different dimensions</source>
        <translation>点集的维数不同</translation>
    </message>
    <message>
        <source>too few points for box counting</source>
        <translation>点太少，无法进行盒计数</translation>
    </message>
    <message>
        <source>all points coincide</source>
        <translation>所有点都重合</translation>
    </message>
    <message>
        <source>not enough points for three box sizes with at least %1 points per box</source>
        <translation>点数不足，无法得到三种每盒至少含 %1 个点的盒尺寸</translation>
    </message>
    <message>
        <source>the joint spectral radius needs at least one matrix</source>
        <translation>联合谱半径至少需要一个矩阵</translation>
    </message>
    <message>
        <source>the joint spectral radius needs square matrices of one size; matrix %1 differs</source>
        <translation>联合谱半径需要尺寸相同的方阵；矩阵 %1 与其他矩阵不同</translation>
    </message>
    <message>
        <source>matrix %1</source>
        <translation>矩阵 %1</translation>
    </message>
    <message>
        <source>not convergent: the first difference scheme does not contract (JSR &gt;= 1)</source>
        <translation>不收敛：一阶差分格式不压缩（JSR &gt;= 1）</translation>
    </message>
    <message>
        <source>convergence not certified within the time budget</source>
        <translation>在时间预算内未能验证收敛性</translation>
    </message>
    <message>
        <source>C^%1, Hölder regularity in [%2, %3]</source>
        <translation>C^%1，Hölder 正则性位于 [%2, %3] 内</translation>
    </message>
    <message>
        <source>cancelled; the bounds are those reached. </source>
        <translation>已取消；所给的界为目前已达到的界。 </translation>
    </message>
    <message>
        <source>time budget spent; the bounds are those reached. </source>
        <translation>时间预算已用完；所给的界为目前已达到的界。 </translation>
    </message>
    <message>
        <source>not convergent</source>
        <translation>不收敛</translation>
    </message>
    <message>
        <source>C^0 not certified</source>
        <translation>未能验证 C^0</translation>
    </message>
    <message>
        <source>the arity of a scheme must be at least 2, got %1</source>
        <translation>细分格式的元数必须至少为 2，实际为 %1</translation>
    </message>
    <message>
        <source>the mask has a coefficient that is not a finite number</source>
        <translation>掩模中有一个系数不是有限数</translation>
    </message>
    <message>
        <source>no difference scheme: the mask is zero</source>
        <translation>不存在差分格式：掩模为零</translation>
    </message>
    <message>
        <source>no difference scheme: the symbol a(z) has no factor 1 + z%1 (the rules&apos; weights do not each sum to 1), so the scheme does not reproduce constants and is not convergent</source>
        <translation>不存在差分格式：符号 a(z) 没有因子 1 + z%1（各规则的权值之和并非都为 1），因此该格式不能再生常数，也不收敛</translation>
    </message>
    <message>
        <source>not convergent: the mask sums to %1, not the arity %2 (the scheme does not reproduce constants)</source>
        <translation>不收敛：掩模之和为 %1，而不是元数 %2（该格式不能再生常数）</translation>
    </message>
    <message>
        <source>the upper bound is the exact Hölder exponent only if the integer shifts of the basic limit function are stable (not checked for this mask). </source>
        <translation>仅当基本极限函数的整数平移稳定时，上界才是精确的 Hölder 指数（未对此掩模检查该条件）。 </translation>
    </message>
    <message>
        <source>regularity needs at least two subdivision matrices</source>
        <translation>正则性分析至少需要两个细分矩阵</translation>
    </message>
    <message>
        <source>the subdivision matrices must all be square and of one size</source>
        <translation>细分矩阵必须都是尺寸相同的方阵</translation>
    </message>
    <message>
        <source>matrix S_%1</source>
        <translation>矩阵 S_%1</translation>
    </message>
    <message>
        <source>no difference scheme: the rows of S_%1 do not all sum to 1</source>
        <translation>不存在差分格式：S_%1 的各行之和并非都为 1</translation>
    </message>
    <message>
        <source>no regularity: S_1 or S_p has no simple eigenvalue 1, so the curve&apos;s end points are not defined</source>
        <translation>无正则性：S_1 或 S_p 没有单重特征值 1，因此曲线的端点没有定义</translation>
    </message>
    <message>
        <source>no regularity: the pieces S_%1 and S_%2 do not join (the attractor is not a continuous curve in its %3-adic parameter)</source>
        <translation>无正则性：片段 S_%1 与 S_%2 不相接（吸引子关于其 %3 进参数不是连续曲线）</translation>
    </message>
    <message>
        <source>C^infinity: the curve is one polynomial piece of degree %1</source>
        <translation>C^infinity：该曲线是单个 %1 次多项式片段</translation>
    </message>
    <message>
        <source>the matrices reproduce every polynomial of degree &lt; %1 in the %2-adic parameter and leave no complement</source>
        <translation>这些矩阵再生关于 %2 进参数的所有次数 &lt; %1 的多项式，且不留补空间</translation>
    </message>
    <message>
        <source>the upper bound assumes the curve&apos;s basis functions are stable. </source>
        <translation>上界假定曲线的基函数是稳定的。 </translation>
    </message>
    <message>
        <source>the pieces join only C^%1 (derivative %2 differs across a join). </source>
        <translation>各片段仅以 C^%1 相接（%2 阶导数在接合处不同）。 </translation>
    </message>
    <message>
        <source>C^infinity: a Bézier curve is a polynomial of degree %1</source>
        <translation>C^infinity：Bézier 曲线是 %1 次多项式</translation>
    </message>
    <message>
        <source>de Casteljau subdivision reproduces the Bézier polynomial exactly</source>
        <translation>de Casteljau 细分精确地再生 Bézier 多项式</translation>
    </message>
    <message>
        <source>eigenvalues need a square matrix</source>
        <translation>特征值计算需要方阵</translation>
    </message>
    <message>
        <source>matrix</source>
        <translation>矩阵</translation>
    </message>
    <message>
        <source>the eigenvalue computation did not converge</source>
        <translation>特征值计算未收敛</translation>
    </message>
    <message>
        <source>no subdominant eigenvalue (the map is constant)</source>
        <translation>没有次占优特征值（该映射是常值映射）</translation>
    </message>
    <message>
        <source>real positive: the curve has a half-tangent at the fixed point, along the eigenvector (G1 where the two sides&apos; eigenvectors align)</source>
        <translation>正实数：曲线在不动点处沿特征向量方向有单侧切线（两侧特征向量方向一致时为 G1）</translation>
    </message>
    <message>
        <source>real positive but repeated: the tangent direction at the fixed point depends on the control points</source>
        <translation>正实数但为重特征值：不动点处的切线方向取决于控制点</translation>
    </message>
    <message>
        <source>real negative: the curve oscillates at the fixed point and has no tangent there</source>
        <translation>负实数：曲线在不动点处振荡，该处没有切线</translation>
    </message>
    <message>
        <source>complex pair: the curve spirals around the fixed point (no tangent)</source>
        <translation>共轭复数对：曲线绕不动点螺旋（没有切线）</translation>
    </message>
    <message>
        <source>complex: near the fixed point the map acts as the spiral similarity z -&gt; lambda z, so the curve spirals around the fixed point (no tangent)</source>
        <translation>复数：在不动点附近，该映射作用为螺旋相似变换 z -&gt; lambda z，因此曲线绕不动点螺旋（没有切线）</translation>
    </message>
    <message>
        <source>several eigenvalues of the same modulus with different signs or phases: no single tangent behaviour</source>
        <translation>存在多个模相同但符号或相位不同的特征值：没有单一的切线行为</translation>
    </message>
    <message>
        <source>not contractive: spectral radius %1 &gt;= 1</source>
        <translation>非压缩：谱半径 %1 &gt;= 1</translation>
    </message>
    <message>
        <source>contractive (factor ||A||_2 = %1)</source>
        <translation>压缩（压缩因子 ||A||_2 = %1）</translation>
    </message>
    <message>
        <source>eventually contractive (spectral radius %1 &lt; 1; ||A^%2||_2 &lt; 1)</source>
        <translation>最终压缩（谱半径 %1 &lt; 1；||A^%2||_2 &lt; 1）</translation>
    </message>
    <message>
        <source>eventually contractive (spectral radius %1 &lt; 1)</source>
        <translation>最终压缩（谱半径 %1 &lt; 1）</translation>
    </message>
    <message>
        <source>map %1 is not contractive: the spectral radius of its linear part is %2 &gt;= 1, so the IFS has no attractor (the iteration does not converge)</source>
        <translation>映射 %1 不是压缩的：其线性部分的谱半径为 %2 &gt;= 1，因此该 IFS 没有吸引子（迭代不收敛）</translation>
    </message>
    <message>
        <source>too many points to index</source>
        <translation>要索引的点太多</translation>
    </message>
    <message>
        <source>; but the IFS contracts on average (Lyapunov exponent %1 along the orbit): random iteration draws its attractor</source>
        <translation>；但该 IFS 平均意义下是压缩的（沿轨道的李雅普诺夫指数为 %1）：随机迭代可以绘出其吸引子</translation>
    </message>
    <message>
        <source>a curve needs at least one piece</source>
        <translation>曲线至少需要一段</translation>
    </message>
    <message>
        <source>a Bézier piece needs 2 to 31 plane control points</source>
        <translation>Bézier 段需要 2 到 31 个平面控制点</translation>
    </message>
    <message>
        <source>a Bézier piece</source>
        <translation>一个 Bézier 段</translation>
    </message>
    <message>
        <source>a Takagi image needs 2 to 31 control points</source>
        <translation>Takagi 图像需要 2 到 31 个控制点</translation>
    </message>
    <message>
        <source>the control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>a Takagi image needs a finite |y| &lt;= 1</source>
        <translation>Takagi 图像需要有限的 |y| &lt;= 1</translation>
    </message>
    <message>
        <source>the Hausdorff bracket needs a nonempty set of plane points</source>
        <translation>Hausdorff 区间需要非空的平面点集</translation>
    </message>
    <message>
        <source>the point set</source>
        <translation>点集</translation>
    </message>
    <message>
        <source>the s.m.p. candidate&apos;s leading eigenvalue is complex (%1); the complex-polytope variant is not implemented</source>
        <translation>s.m.p. 候选的主特征值为复数（%1）；复多面体变体尚未实现</translation>
    </message>
    <message>
        <source>the s.m.p. candidate&apos;s leading eigenvalue is not simple in modulus (not a dominant product)</source>
        <translation>s.m.p. 候选的主特征值按模不是单一的（不是占优乘积）</translation>
    </message>
    <message>
        <source>no real leading eigenvector</source>
        <translation>没有实的主特征向量</translation>
    </message>
    <message>
        <source>invariant polytope: cancelled</source>
        <translation>不变多面体：已取消</translation>
    </message>
    <message>
        <source>invariant polytope did not close in the budget (%1 vertices)</source>
        <translation>不变多面体未能在预算内闭合（%1 个顶点）</translation>
    </message>
    <message>
        <source>invariant polytope did not close within %1 vertices</source>
        <translation>不变多面体在 %1 个顶点内未闭合</translation>
    </message>
    <message>
        <source>JSR = 0: the matrices are empty or zero</source>
        <translation>JSR = 0：矩阵为空或为零</translation>
    </message>
    <message>
        <source>every product up to length %1 has spectral radius 0: no s.m.p. candidate</source>
        <translation>长度不超过 %1 的所有乘积的谱半径均为 0：没有 s.m.p. 候选</translation>
    </message>
    <message>
        <source>the family is numerically nilpotent (every product of length L vanishes to rounding): JSR = 0, no s.m.p. to certify</source>
        <translation>该矩阵族在数值上是幂零的（每个长度为 L 的乘积在舍入误差范围内为零）：JSR = 0，没有可认证的 s.m.p.</translation>
    </message>
    <message>
        <source>the invariant polytope closed but its certificate failed the check: </source>
        <translation>不变多面体已闭合，但其证书未通过检验：</translation>
    </message>
    <message>
        <source>invariant polytope closed: JSR = rho(A_w)^(1/%1) for the s.m.p. w = (%2), %3 vertices</source>
        <translation>不变多面体已闭合：对于 s.m.p. w = (%2)，JSR = rho(A_w)^(1/%1)，%3 个顶点</translation>
    </message>
    <message>
        <source>the invariant polytope&apos;s bracket contradicts the bounds; ignored</source>
        <translation>不变多面体的区间与界相矛盾；已忽略</translation>
    </message>
    <message>
        <source>the parameter range [%1, %2] must be finite with from &lt; to</source>
        <translation>参数范围 [%1, %2] 必须有限且满足 from &lt; to</translation>
    </message>
    <message>
        <source>the smoothness k must be between 0 and 30, got %1</source>
        <translation>光滑度 k 必须介于 0 和 30 之间，实际为 %1</translation>
    </message>
    <message>
        <source>the grid must have 2 to 10000 values, got %1</source>
        <translation>网格必须包含 2 到 10000 个值，实际为 %1</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the mask is zero</source>
        <translation>无 Sobolev 指数：掩模为零</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the symbol has no sum rule (the rules&apos; weights do not each sum to 1), so the scheme does not converge</source>
        <translation>无 Sobolev 指数：符号不满足和规则（各规则的权重并非各自之和为 1），因此该格式不收敛</translation>
    </message>
    <message>
        <source>no Sobolev exponent: the mask sums to %1, not the arity %2 (the refinement equation has no integrable solution with nonzero mean)</source>
        <translation>无 Sobolev 指数：掩模之和为 %1，而不是元数 %2（加细方程没有均值非零的可积解）</translation>
    </message>
    <message>
        <source>no positive Sobolev smoothness: rho = %1 &gt;= 1 (to rounding), so s_2 = %2 &lt;= 0: with stable shifts the basic limit function is in no H^s with s &gt; 0, if it is a function at all</source>
        <translation>无正的 Sobolev 光滑度：rho = %1 &gt;= 1（在舍入误差范围内），因此 s_2 = %2 &lt;= 0：在平移稳定的情况下，基本极限函数不属于任何 s &gt; 0 的 H^s（如果它确实是一个函数的话）</translation>
    </message>
    <message>
        <source>Sobolev exponent s_2 = %1: in H^s for every s &lt; %1</source>
        <translation>Sobolev 指数 s_2 = %1：对所有 s &lt; %1 属于 H^s</translation>
    </message>
    <message>
        <source> (capped at the %1 sum rules; -log_N(rho) / 2 = %2)</source>
        <translation>（受 %1 条和规则限制；-log_N(rho) / 2 = %2）</translation>
    </message>
    <message>
        <source>not analysed: the mask has %1 coefficients, the regularity analysis takes at most %2 for arity %3 (transition matrices up to 48 x 48)</source>
        <translation>未分析：该掩模有 %1 个系数，对于元数 %3，正则性分析最多接受 %2 个（转移矩阵最大 48 x 48）</translation>
    </message>
    <message>
        <source>; exact by the invariant polytope algorithm (Guglielmi &amp; Protasov 2013): s.m.p. (%1), %2 vertices</source>
        <translation>; 由不变多面体算法（Guglielmi &amp; Protasov 2013）得到精确值：s.m.p. (%1)，%2 个顶点</translation>
    </message>
    <message>
        <source>JSR of %1 matrices %2 x %2</source>
        <translation>%1 个 %2 x %2 矩阵的 JSR</translation>
    </message>
    <message>
        <source>: lower bound max rho(product)^(1/k) over all products up to length %1</source>
        <translation>: 下界 max rho(product)^(1/k)，取遍长度不超过 %1 的所有乘积</translation>
    </message>
    <message>
        <source> and the branch&apos;s products up to length %1</source>
        <translation> 以及分支中长度不超过 %1 的乘积</translation>
    </message>
    <message>
        <source>, upper bound by Gripenberg&apos;s branch and bound (1996) in the %1</source>
        <translation>, 上界由 Gripenberg 分支定界法（1996）在 %1 下求得</translation>
    </message>
    <message>
        <source>, upper bound in the %1</source>
        <translation>, 上界在 %1 下求得</translation>
    </message>
    <message>
        <source> (equal to the lower bound)</source>
        <translation> (等于下界)</translation>
    </message>
    <message>
        <source>, %1 products</source>
        <translation>, %1 个乘积</translation>
    </message>
    <message>
        <source>r = n - log_%1 rho_n with n = %2 (a(z) has the factor (%3)^%2), rho_n the joint spectral radius of the transition matrices of the divided-difference mask of order %2 (Daubechies &amp; Lagarias 1992, Rioul 1992); %4%5</source>
        <translation>r = n - log_%1 rho_n，其中 n = %2（a(z) 含因子 (%3)^%2），rho_n 为 %2 阶差商掩模的转移矩阵的联合谱半径（Daubechies &amp; Lagarias 1992，Rioul 1992）；%4%5</translation>
    </message>
    <message>
        <source>r = -log_%1 rho with rho the joint spectral radius of S_1..S_%1 on the quotient by the control vectors of the polynomials of degree &lt; %2 that they generate (Micchelli &amp; Prautzsch 1989); %3%4</source>
        <translation>r = -log_%1 rho，其中 rho 为 S_1..S_%1 在商空间上的联合谱半径，该商空间是模去生成次数 &lt; %2 的多项式的控制向量所得（Micchelli &amp; Prautzsch 1989）；%3%4</translation>
    </message>
    <message>
        <source>s_2 = -log_%1(rho) / 2 with rho the spectral radius of the transition operator (T v)_i = sum_j b_{%1i - j} v_j of the autocorrelation b_k = (1/%1) sum_j a_j a_{j+k} on [-%2, %2], restricted to the %3-dimensional invariant subspace orthogonal to the polynomials of degree &lt; %4 (Eirola 1992, Villemoes 1994, Jia 1999); exact for stable integer shifts, a lower bound otherwise (Ron &amp; Shen 2000); rounding margin %5</source>
        <translation>s_2 = -log_%1(rho) / 2，其中 rho 为自相关 b_k = (1/%1) sum_j a_j a_{j+k} 的转移算子 (T v)_i = sum_j b_{%1i - j} v_j 在 [-%2, %2] 上、限制于与次数 &lt; %4 的多项式正交的 %3 维不变子空间时的谱半径（Eirola 1992，Villemoes 1994，Jia 1999）；整数平移稳定时为精确值，否则为下界（Ron &amp; Shen 2000）；舍入余量 %5</translation>
    </message>
    <message>
        <source>work budget spent; the bounds are those reached. </source>
        <translation>计算预算已用尽；给出的是已达到的上下界。</translation>
    </message>
    <message>
        <source>an atlas has one or two parameters, got %1</source>
        <translation>图谱应有一个或两个参数，实际为 %1</translation>
    </message>
    <message>
        <source>a parameter of the atlas has no name</source>
        <translation>图谱的某个参数没有名称</translation>
    </message>
    <message>
        <source>the range of %1, [%2, %3], must be finite with from &lt; to</source>
        <translation>%1 的范围 [%2, %3] 必须有限，且“从” &lt; “到”</translation>
    </message>
    <message>
        <source>the grid of %1 must have 2 to %2 values, got %3</source>
        <translation>%1 的网格必须有 2 到 %2 个值，实际为 %3</translation>
    </message>
    <message>
        <source>the two parameters of the atlas have the same name %1</source>
        <translation>图谱的两个参数同名 %1</translation>
    </message>
    <message>
        <source>the tolerance must be a positive number</source>
        <translation>容差必须为正数</translation>
    </message>
    <message>
        <source>the sections per round must be 1 to 64</source>
        <translation>每轮的分段数必须为 1 到 64</translation>
    </message>
    <message>
        <source>the rounds must be 0 to 64</source>
        <translation>轮数必须为 0 到 64</translation>
    </message>
    <message>
        <source>the refinement levels must be 0 to 10, got %1</source>
        <translation>细化层数必须为 0 到 10，实际为 %1</translation>
    </message>
    <message>
        <source>the work per point must be 1000 to 1e11 products</source>
        <translation>每个点的计算量必须为 1000 到 1e11 次乘积</translation>
    </message>
    <message>
        <source>the polytope vertices must be 0 to 100000</source>
        <translation>多面体顶点数必须为 0 到 100000</translation>
    </message>
    <message>
        <source>the safety time must be 0 to 86400 s</source>
        <translation>安全时限必须为 0 到 86400 秒</translation>
    </message>
    <message>
        <source>a grid of %1 x %2 points is more than the atlas&apos;s 1e6</source>
        <translation>%1 x %2 个点的网格超过了图谱的上限 1e6</translation>
    </message>
    <message>
        <source>the atlas&apos;s previous batch has no rows yet</source>
        <translation>图谱的上一批次还没有任何行</translation>
    </message>
    <message>
        <source>the atlas expected %1 rows, got %2</source>
        <translation>图谱应有 %1 行，实际为 %2 行</translation>
    </message>
    <message>
        <source>a row of the atlas does not belong to its batch</source>
        <translation>图谱的某一行不属于其批次</translation>
    </message>
    <message>
        <source>map %1 is not contractive: its map of the plane has spectral radius %2 &gt;= 1 (%3 in the lifted space of its control points), so the IFS has no attractor (the iteration does not converge)</source>
        <translation>映射 %1 不是压缩的：它在平面上的映射的谱半径为 %2 &gt;= 1（在其控制点的提升空间中为 %3），因此该 IFS 没有吸引子（迭代不收敛）</translation>
    </message>
    <message>
        <source>map %1 is not contractive in the lifted space of its control points (spectral radius %3 &gt;= 1), although its map of the plane contracts (spectral radius %2): the lifted iteration does not converge</source>
        <translation>映射 %1 在其控制点的提升空间中不是压缩的（谱半径 %3 &gt;= 1），尽管它在平面上的映射是压缩的（谱半径 %2）：提升空间中的迭代不收敛</translation>
    </message>
</context>
<context>
    <name>awb::cli</name>
    <message>
        <source>Render the bundled paper figures to PNG files (one row of panels per figure: the start set, a few iterates of the Hutchinson operator, and the attractor, over the control polygon).</source>
        <translation>将内置的论文图形渲染为 PNG 文件（每个图形一行面板：初始集、Hutchinson 算子的若干次迭代结果以及吸引子，叠加在控制多边形上）。</translation>
    </message>
    <message>
        <source>Directory for the PNG files (created if missing).</source>
        <translation>PNG 文件的输出目录（不存在时自动创建）。</translation>
    </message>
    <message>
        <source>List the examples and exit.</source>
        <translation>列出示例并退出。</translation>
    </message>
    <message>
        <source>attractor-cli: cannot create directory %1</source>
        <translation>attractor-cli：无法创建目录 %1</translation>
    </message>
    <message>
        <source>attractor-cli: unknown command &apos;%1&apos;</source>
        <translation>attractor-cli：未知命令“%1”</translation>
    </message>
    <message>
        <source>expected %1 project file, got %2 arguments (see --help)</source>
        <translation>应为 %1 个项目文件，实际给出 %2 个参数（参见 --help）</translation>
    </message>
    <message>
        <source>no item named &apos;%1&apos; in %2</source>
        <translation>%2 中没有名为“%1”的对象</translation>
    </message>
    <message>
        <source>the figure&apos;s project</source>
        <translation>该图形所属的项目</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no attractor</source>
        <translation>对象“%1”（%2）没有吸引子</translation>
    </message>
    <message>
        <source>%1 has no item with an attractor</source>
        <translation>%1 中没有带吸引子的对象</translation>
    </message>
    <message>
        <source>item &apos;%1&apos;: %2</source>
        <translation>对象“%1”：%2</translation>
    </message>
    <message>
        <source>--%1 must be a whole number from %2 to %3, got &apos;%4&apos;</source>
        <translation>--%1 必须是 %2 到 %3 之间的整数，实际为“%4”</translation>
    </message>
    <message>
        <source>--%1 must be a number from %2 to %3, got &apos;%4&apos;</source>
        <translation>--%1 必须是 %2 到 %3 之间的数，实际为“%4”</translation>
    </message>
    <message>
        <source>--start: &apos;%1&apos; is not a finite number</source>
        <translation type="vanished">--start：“%1”不是有限数</translation>
    </message>
    <message>
        <source>--start must be point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;..., got &apos;%1&apos;</source>
        <translation type="vanished">--start 的格式必须为 point:x,y | segment:x1,y1,x2,y2 | triangle:x1,y1,x2,y2,x3,y3 | polygon:... | points:... | lifted:x,y,c1,...;...，实际为“%1”</translation>
    </message>
    <message>
        <source>--start %1 needs %2 coordinates (%3 per point), got %4</source>
        <translation type="vanished">--start %1 需要 %2 个坐标（每个点 %3 个），实际为 %4 个</translation>
    </message>
    <message>
        <source>a multiple of %1</source>
        <translation type="vanished">%1 的倍数</translation>
    </message>
    <message>
        <source>depth %1 gives %2 points, more than --max-points %3</source>
        <translation>深度 %1 将产生 %2 个点，超过 --max-points %3</translation>
    </message>
    <message>
        <source>Image size in pixels (default 900x700).</source>
        <translation>图像尺寸，单位为像素（默认 900x700）。</translation>
    </message>
    <message>
        <source>Deterministic iteration depth (default: the item&apos;s).</source>
        <translation>确定性迭代深度（默认：对象自身的深度）。</translation>
    </message>
    <message>
        <source>Random iteration with this many points (up to 1e12; memory stays that of the raster).</source>
        <translation>使用指定数目的点进行随机迭代（最多 1e12；内存占用只取决于栅格大小）。</translation>
    </message>
    <message>
        <source>Raster tone: &apos;hits&apos; (every lit pixel opaque, the papers&apos; look) or &apos;density&apos; (log density of the invariant measure, gamma and vibrancy as flame renderers). Default: the item&apos;s style (auto: hits for deterministic, density for random iteration).</source>
        <translation>栅格色调：&apos;hits&apos;（每个被击中的像素都不透明，即论文中的效果）或 &apos;density&apos;（不变测度的对数密度，gamma 和 vibrancy 的含义与分形火焰渲染器相同）。默认：对象自身的样式（auto：确定性迭代用 hits，随机迭代用 density）。</translation>
    </message>
    <message>
        <source>Density tone: display gamma (default: the item&apos;s, 2.2).</source>
        <translation>密度色调：显示 gamma（默认：对象自身的值，2.2）。</translation>
    </message>
    <message>
        <source>Density tone: 1 saturated colours, 0 per-channel gamma (default 1).</source>
        <translation>密度色调：1 表示饱和色，0 表示逐通道 gamma（默认 1）。</translation>
    </message>
    <message>
        <source>Histogram cells per pixel side, 1..4 (default 1; 2 or 3 anti-alias edges).</source>
        <translation>每个像素每边的直方图单元数，1..4（默认 1；取 2 或 3 可对边缘抗锯齿）。</translation>
    </message>
    <message>
        <source>Threads of the raster engine (default: all cores).</source>
        <translation>栅格引擎的线程数（默认：全部核心）。</translation>
    </message>
    <message>
        <source>Surfaces: the camera&apos;s azimuth and elevation in degrees (orthographic; default: the item&apos;s camera).</source>
        <translation>曲面：相机的方位角和仰角，单位为度（正交投影；默认：对象自身的相机）。</translation>
    </message>
    <message>
        <source>Plane figures: the world rectangle to frame (padded by 6%), e.g. to compare figures at one scale (default: fit the content).</source>
        <translation>平面图形：要框选的世界坐标矩形（四周留出 6% 边距），例如用于以同一比例比较多个图形（默认：适应内容）。</translation>
    </message>
    <message>
        <source>The output&apos;s format when its name has no suffix (e.g. /dev/stdout): png, svg or pdf (default: the suffix).</source>
        <translation type="vanished">输出文件名没有后缀时（例如 /dev/stdout）所用的格式：png、svg 或 pdf（默认：由后缀决定）。</translation>
    </message>
    <message>
        <source>--depth and --samples exclude each other</source>
        <translation>--depth 与 --samples 不能同时使用</translation>
    </message>
    <message>
        <source>--size must be WxH with 64..16384 pixels each, got &apos;%1&apos;</source>
        <translation>--size 的格式必须为 WxH，每边 64..16384 像素，实际为“%1”</translation>
    </message>
    <message>
        <source>--tone must be &apos;hits&apos; or &apos;density&apos;, got &apos;%1&apos;</source>
        <translation>--tone 必须为 &apos;hits&apos; 或 &apos;density&apos;，实际为“%1”</translation>
    </message>
    <message>
        <source>--bounds must be x0,y0,x1,y1 with x0 &lt; x1 and y0 &lt; y1, got &apos;%1&apos;</source>
        <translation>--bounds 的格式必须为 x0,y0,x1,y1，且 x0 &lt; x1、y0 &lt; y1，实际为“%1”</translation>
    </message>
    <message>
        <source>--format must be png, svg or pdf, got &apos;%1&apos;</source>
        <translation type="vanished">--format 必须为 png、svg 或 pdf，实际为“%1”</translation>
    </message>
    <message>
        <source>depth %1 makes %2 images; at most 4e9 are rendered</source>
        <translation type="vanished">深度 %1 将产生 %2 个像；最多渲染 4e9 个</translation>
    </message>
    <message>
        <source>--view must be AZ,EL in degrees with |EL| &lt;= 90, got &apos;%1&apos;</source>
        <translation>--view 的格式必须为 AZ,EL（单位为度），且 |EL| &lt;= 90，实际为“%1”</translation>
    </message>
    <message>
        <source>%1 random points</source>
        <translation type="vanished">%1 个随机点</translation>
    </message>
    <message>
        <source>F^%1(X0)</source>
        <translation type="vanished">F^%1(X0)</translation>
    </message>
    <message>
        <source>, maps %1 of %2</source>
        <translation type="vanished">，使用映射 %1（共 %2 个）</translation>
    </message>
    <message>
        <source>%1: %2%3 — orthographic view from azimuth %4°, elevation %5°</source>
        <translation type="vanished">%1：%2%3 — 从方位角 %4°、仰角 %5° 观察的正交视图</translation>
    </message>
    <message>
        <source>%1: %2 random points</source>
        <translation type="vanished">%1：%2 个随机点</translation>
    </message>
    <message>
        <source>%1: F^%2(X0)</source>
        <translation type="vanished">%1：F^%2(X0)</translation>
    </message>
    <message>
        <source>%1: polygon after %2 steps</source>
        <translation type="vanished">%1：%2 步之后的多边形</translation>
    </message>
    <message>
        <source>Render an item&apos;s attractor (with its control polygons) to PNG, SVG or PDF.</source>
        <translation type="vanished">将对象的吸引子（连同其控制多边形）渲染为 PNG、SVG 或 PDF。</translation>
    </message>
    <message>
        <source>The .awb project file.</source>
        <translation>.awb 项目文件。</translation>
    </message>
    <message>
        <source>The item to render (default: the first with an attractor).</source>
        <translation>要渲染的对象（默认：第一个带吸引子的对象）。</translation>
    </message>
    <message>
        <source>Output file: .png, .svg or .pdf.</source>
        <translation type="vanished">输出文件：.png、.svg 或 .pdf。</translation>
    </message>
    <message>
        <source>--out FILE is required</source>
        <translation>必须提供 --out FILE</translation>
    </message>
    <message>
        <source>Render the frames of an item&apos;s animation (its keyframed parameters): numbered PNG files in a folder, or an MP4 or GIF movie through ffmpeg. Frame k is the item with its parameters at time k / fps, drawn exactly as `render` draws it.</source>
        <translation>渲染对象动画（其设置了关键帧的参数）的各帧：输出为文件夹中带编号的 PNG 文件，或通过 ffmpeg 生成 MP4 或 GIF 影片。第 k 帧是参数取时间 k / fps 处取值时的对象，绘制方式与 `render` 完全相同。</translation>
    </message>
    <message>
        <source>The animated item (default: the first item with an animation).</source>
        <translation>要制作动画的对象（默认：第一个带动画的对象）。</translation>
    </message>
    <message>
        <source>A folder for frame-0000.png, frame-0001.png, ... (made if missing), a movie .mp4 or .gif (made by ffmpeg), or with --frame one .png/.svg/.pdf.</source>
        <translation>用于存放 frame-0000.png、frame-0001.png、... 的文件夹（不存在时自动创建），或一个 .mp4 或 .gif 影片（由 ffmpeg 生成），或配合 --frame 使用时为单个 .png/.svg/.pdf 文件。</translation>
    </message>
    <message>
        <source>Frames per second (default: the animation&apos;s).</source>
        <translation>每秒帧数（默认：动画自身的设置）。</translation>
    </message>
    <message>
        <source>Render only frame K (0 = the start) to the file --out.</source>
        <translation>只将第 K 帧（0 = 起始帧）渲染到 --out 指定的文件。</translation>
    </message>
    <message>
        <source>Captions without the frame&apos;s time and values.</source>
        <translation>标题中不含该帧的时间和参数值。</translation>
    </message>
    <message>
        <source>--out DIR|FILE is required</source>
        <translation>必须提供 --out DIR|FILE</translation>
    </message>
    <message>
        <source>%1 has no animated item</source>
        <translation>%1 中没有带动画的对象</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; has no animation: key its parameters in the Animation dock, or give it an &quot;animation&quot; field (docs/file-format.md)</source>
        <translation>对象“%1”没有动画：请在“动画”面板中为其参数设置关键帧，或为其添加 &quot;animation&quot; 字段（docs/file-format.md）</translation>
    </message>
    <message>
        <source>attractor-cli: note: the track of %1 is skipped: item &apos;%2&apos; has no such input now</source>
        <translation>attractor-cli：注意：已跳过 %1 的轨道：对象“%2”当前没有该输入</translation>
    </message>
    <message>
        <source>%1,%2,%3,%4</source>
        <translation>%1,%2,%3,%4</translation>
    </message>
    <message>
        <source>fitted per frame</source>
        <translation>逐帧适应</translation>
    </message>
    <message>
        <source>frame %1 (t = %2 s): %3</source>
        <translation>第 %1 帧（t = %2 s）：%3</translation>
    </message>
    <message>
        <source>writing %1 needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg); give --out a folder to get the frames as PNG files</source>
        <translation>写入 %1 需要 ffmpeg，但它尚未安装（Debian：apt-get install ffmpeg）；若为 --out 指定一个文件夹，则可得到各帧的 PNG 文件</translation>
    </message>
    <message>
        <source>cannot make a temporary folder for the frames: %1</source>
        <translation>无法为各帧创建临时文件夹：%1</translation>
    </message>
    <message>
        <source>%1 is a file, not a folder (a movie needs .mp4 or .gif)</source>
        <translation>%1 是文件而不是文件夹（影片需要 .mp4 或 .gif 后缀）</translation>
    </message>
    <message>
        <source>cannot make the folder %1</source>
        <translation>无法创建文件夹 %1</translation>
    </message>
    <message>
        <source>frame-%1.png</source>
        <translation>frame-%1.png</translation>
    </message>
    <message>
        <source>ffmpeg could not write %1: %2</source>
        <translation>ffmpeg 无法写入 %1：%2</translation>
    </message>
    <message>
        <source>%1: %2 frames of %3x%4 at %5 frames/s (%6 s); rendered in %7 s, %8 frames/s
bounds: %9
</source>
        <translation>%1：%2 帧，%3x%4，%5 帧/s（%6 s）；渲染耗时 %7 s，%8 帧/s
范围：%9
</translation>
    </message>
    <message>
        <source>Analyse the items of a project: per map S_i (exact fractions), M_i = P^-1 S_i P with its blocks A_i, b_i, the eigenvalues of S_i and A_i, spectral radius, contractivity and fixed point; per item the subdominant eigenvalues, the Hausdorff distance to the exact curve and the box-counting dimension; per subdivision curve the certified Hölder regularity of its scheme.</source>
        <translation>分析项目中的对象：对每个映射给出 S_i（精确分数）、M_i = P^-1 S_i P 及其分块 A_i、b_i，S_i 与 A_i 的特征值，谱半径、压缩性和不动点；对每个对象给出次占优特征值、到精确曲线的 Hausdorff 距离以及盒计数维数；对每条细分曲线给出其细分格式经验证的 Hölder 正则性。</translation>
    </message>
    <message>
        <source>Only this item.</source>
        <translation>仅此对象。</translation>
    </message>
    <message>
        <source>Print JSON (the only format so far).</source>
        <translation>输出 JSON（目前唯一的格式）。</translation>
    </message>
    <message>
        <source>--json is required (the only output format)</source>
        <translation>必须提供 --json（唯一的输出格式）</translation>
    </message>
    <message>
        <source>Print the points of F^k(X0) as CSV: x, y (and z for a surface), the map applied last (1-based), and the view. --address w limits them to the sub-copy f_w(A): the points f_w(F^k(X0)).</source>
        <translation>以 CSV 格式输出 F^k(X0) 的点：x、y（曲面还有 z）、最后作用的映射（从 1 开始编号）以及视图。--address w 将其限制在子副本 f_w(A) 内：即点 f_w(F^k(X0))。</translation>
    </message>
    <message>
        <source>The item.</source>
        <translation type="vanished">对象。</translation>
    </message>
    <message>
        <source>Iteration depth (default: the item&apos;s).</source>
        <translation>迭代深度（默认：对象自身的深度）。</translation>
    </message>
    <message>
        <source>Print CSV (the only format so far).</source>
        <translation>输出 CSV（目前唯一的格式）。</translation>
    </message>
    <message>
        <source>Only the sub-copy f_w(A) of this address: 0-based map numbers, w_1 (the outermost map) first, e.g. 0,1,1.</source>
        <translation>只输出该地址对应的子副本 f_w(A)：映射从 0 开始编号，w_1（最外层的映射）在前，例如 0,1,1。</translation>
    </message>
    <message>
        <source>Refuse to print more (default 10000000).</source>
        <translation>超过此数目时拒绝输出（默认 10000000）。</translation>
    </message>
    <message>
        <source>--item NAME is required</source>
        <translation type="vanished">必须提供 --item NAME</translation>
    </message>
    <message>
        <source>--csv is required (the only output format)</source>
        <translation>必须提供 --csv（唯一的输出格式）</translation>
    </message>
    <message>
        <source>--address %1: %2</source>
        <translation>--address %1：%2</translation>
    </message>
    <message>
        <source>--start lifted: needs at least one point</source>
        <translation type="vanished">--start lifted：至少需要一个点</translation>
    </message>
    <message>
        <source>cannot write to the standard output</source>
        <translation>无法写入标准输出</translation>
    </message>
    <message>
        <source>Validate a project file: it must load, and every item&apos;s IFS must be computable (exit 1: the file is refused; exit 3: it loads but items cannot be computed).</source>
        <translation>验证项目文件：它必须能够加载，并且每个对象的 IFS 都必须可以计算（退出码 1：文件被拒绝；退出码 3：文件可以加载，但有对象无法计算）。</translation>
    </message>
    <message>
        <source>%1: %2: note: %3</source>
        <translation>%1：%2：注意：%3</translation>
    </message>
    <message>
        <source>Load a project and save it again in the canonical form of this version (sorted keys, every field written): to upgrade or normalise a hand-written file.</source>
        <translation>加载项目并以当前版本的规范形式重新保存（键按字母排序，写出所有字段）：用于升级或规范化手写的文件。</translation>
    </message>
    <message>
        <source>Write here instead of over the input.</source>
        <translation>写入此处，而不是覆盖输入文件。</translation>
    </message>
    <message>
        <source>v %1 %2 %3
</source>
        <translation>v %1 %2 %3
</translation>
    </message>
    <message>
        <source>ply (attractor points) or obj (subdivided mesh).</source>
        <translation type="vanished">ply（吸引子的点）或 obj（细分网格）。</translation>
    </message>
    <message>
        <source>Output file.</source>
        <translation>输出文件。</translation>
    </message>
    <message>
        <source>PLY: iteration depth (default: the item&apos;s).</source>
        <translation>PLY：迭代深度（默认：对象自身的深度）。</translation>
    </message>
    <message>
        <source>PLY: refuse to write more (default 50000000).</source>
        <translation>PLY：超过此数目时拒绝写入（默认 50000000）。</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj and --out FILE are required</source>
        <translation type="vanished">必须提供 --item NAME、--format ply|obj 和 --out FILE</translation>
    </message>
    <message>
        <source>--format must be ply or obj, got &apos;%1&apos;</source>
        <translation type="vanished">--format 必须为 ply 或 obj，实际为“%1”</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>OBJ export writes the subdivided net of a surface item; &apos;%1&apos; is a %2</source>
        <translation>OBJ 导出写出曲面对象的细分控制网格；而“%1”的类型为 %2</translation>
    </message>
    <message>
        <source>Print the control polygon after K subdivision steps as JSON {&quot;closed&quot;, &quot;points&quot;}: the figures of 001 for a normal-vector item (eq. (1) applied K times), classic subdivision S_w P for a subdivision curve.</source>
        <translation>以 JSON {&quot;closed&quot;, &quot;points&quot;} 格式输出 K 步细分后的控制多边形：对于法向量对象为 001 中的图形（将 eq. (1) 应用 K 次），对于细分曲线为经典细分 S_w P。</translation>
    </message>
    <message>
        <source>Subdivision steps K (0: the control polygon).</source>
        <translation>细分步数 K（0：控制多边形本身）。</translation>
    </message>
    <message>
        <source>Print JSON (the only format).</source>
        <translation>输出 JSON（唯一的格式）。</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; has a complex split parameter: its control polygon has complex points</source>
        <translation>对象“%1”具有复分割参数：其控制多边形含有复数点</translation>
    </message>
    <message>
        <source>level %1 gives more than 5e7 points</source>
        <translation>第 %1 层将产生超过 5e7 个点</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) is not polygon-based: the polygon command takes normal-vector items and subdivision curves</source>
        <translation>对象“%1”（%2）不是基于多边形的：polygon 命令只接受法向量对象和细分曲线</translation>
    </message>
    <message>
        <source>nothing to draw</source>
        <translation>没有可绘制的内容</translation>
    </message>
    <message>
        <source>Make a project of a mesh file (OBJ, OFF, PLY ASCII or binary): one subdivision-mesh item with the file&apos;s vertices, in its numbering, and its polygons.</source>
        <translation type="vanished">由网格文件（OBJ、OFF、PLY ASCII 或二进制）创建项目：其中包含一个 subdivision-mesh 对象，带有文件中的顶点（保留文件的编号）及其多边形。</translation>
    </message>
    <message>
        <source>The mesh file.</source>
        <translation>网格文件。</translation>
    </message>
    <message>
        <source>catmull-clark (any polygons, the default) or loop (triangles).</source>
        <translation>catmull-clark（任意多边形，默认）或 loop（三角形）。</translation>
    </message>
    <message>
        <source>The project file to write (.awb).</source>
        <translation>要写入的项目文件（.awb）。</translation>
    </message>
    <message>
        <source>The item&apos;s name (default: the file&apos;s base name).</source>
        <translation>对象名称（默认：不含扩展名的文件名）。</translation>
    </message>
    <message>
        <source>--scheme must be catmull-clark or loop, got &apos;%1&apos;</source>
        <translation>--scheme 必须为 catmull-clark 或 loop，实际为“%1”</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be an item&apos;s name</source>
        <translation>“%1”不能用作对象名称</translation>
    </message>
    <message>
        <source>%1: item &apos;%2&apos;, %3 vertices, %4 faces, %5 extraordinary vertices (%6)
</source>
        <translation>%1：对象“%2”，%3 个顶点，%4 个面，%5 个奇异顶点（%6）
</translation>
    </message>
    <message>
        <source>attractor-cli: note: %1</source>
        <translation type="vanished">attractor-cli：注意：%1</translation>
    </message>
    <message>
        <source>Start set: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (plane coordinates; x,y,z for a surface) | lifted:x,y,c1,...;x,y,c1,... (points of the lifted space of 000 §2) | vertex-limits (a mesh item: the limit positions of the vertices of the mesh refined k times; default: the item&apos;s).</source>
        <translation type="vanished">初始集：point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:...（平面坐标；曲面为 x,y,z）| lifted:x,y,c1,...;x,y,c1,...（000 §2 提升空间中的点）| vertex-limits（网格对象：网格细化 k 次后各顶点的极限位置；默认：对象自身的初始集）。</translation>
    </message>
    <message>
        <source>--start vertex-limits needs a mesh item; &apos;%1&apos; is a %2</source>
        <translation type="vanished">--start vertex-limits 需要网格对象；而“%1”的类型为 %2</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ).</source>
        <translation type="vanished">导出对象的几何：将吸引子 F^k(X0) 导出为 PLY 点云（每个点附带最后作用的映射），将曲面对象经 k 轮经典细分后的控制网格导出为 OBJ 网格，或将网格对象细分 k 步后、每个顶点都置于其极限位置导出（OBJ）。</translation>
    </message>
    <message>
        <source>OBJ: rounds of subdivision (default: the item&apos;s; a mesh item: its depth, at most 6).</source>
        <translation>OBJ：细分轮数（默认：对象自身的设置；网格对象为其深度，最多 6）。</translation>
    </message>
    <message>
        <source>%1 steps give %2 vertices: too many</source>
        <translation type="vanished">%1 步产生 %2 个顶点：过多</translation>
    </message>
    <message>
        <source>Attractor Workbench: item %1, %2 after %3 steps, every vertex at its limit position</source>
        <translation type="vanished">Attractor Workbench：对象 %1，%2 细分 %3 步后，每个顶点都位于其极限位置</translation>
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
        <translation type="vanished">用法：attractor-cli &lt;command&gt; [options]

命令：
  render     将项目中的某个对象渲染为 PNG、SVG 或 PDF
  animate    渲染对象动画的各帧（PNG 文件，MP4/GIF）
  analyse    特征值、压缩性、不动点、维数（JSON）
  points     以 CSV 格式输出 F^k(X0) 的点
  check      验证项目文件
  rewrite    加载项目并以规范形式重新保存
  export     将吸引子的点导出为 PLY，将细分后的控制网格或网格（极限）导出为 OBJ
  polygon    K 步细分后的控制多边形（JSON）
  import-mesh  将网格文件（OBJ、OFF、PLY）导入为含一个网格对象的项目
  examples   将内置的论文图形（000 Figs. 2, 3, 5）渲染为 PNG

运行“attractor-cli &lt;command&gt; --help”查看某个命令的选项。
</translation>
    </message>
    <message>
        <source>--out FILE (the project to write) is required</source>
        <translation>必须提供 --out FILE（要写入的项目）</translation>
    </message>
    <message>
        <source>The spectrum of the local subdivision matrix at an interior vertex of each valence: lambda (with its closed form), mu, lambda^2, Reif&apos;s C1 verdict and the curvature.</source>
        <translation>每个价的内部顶点处局部细分矩阵的谱：lambda（及其闭式）、mu、lambda^2、Reif 的 C1 判定和曲率。</translation>
    </message>
    <message>
        <source>catmull-clark (the default) or loop.</source>
        <translation>catmull-clark（默认）或 loop。</translation>
    </message>
    <message>
        <source>The smallest valence (3 to 64, default 3).</source>
        <translation>最小的价（3 到 64，默认 3）。</translation>
    </message>
    <message>
        <source>The largest valence (3 to 64, default 16).</source>
        <translation>最大的价（3 到 64，默认 16）。</translation>
    </message>
    <message>
        <source>Print JSON instead of a table.</source>
        <translation>输出 JSON 而不是表格。</translation>
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
        <translation type="vanished">用法：attractor-cli &lt;command&gt; [options]

命令：
  render     将项目中的某个对象渲染为 PNG、SVG 或 PDF
  animate    渲染对象动画的各帧（PNG 文件，MP4/GIF）
  analyse    特征值、压缩性、不动点、维数（JSON）
  points     以 CSV 格式输出 F^k(X0) 的点
  check      验证项目文件
  rewrite    加载项目并以规范形式重新保存
  export     将吸引子的点导出为 PLY，将细分后的控制网格或网格（极限）导出为 OBJ
  polygon    K 步细分后的控制多边形（JSON）
  import-mesh  将网格文件（OBJ、OFF、PLY）导入为含一个网格对象的项目
  valences   每个价的 lambda、mu 与 Reif 的 C1 判定（Catmull-Clark、Loop）
  examples   将内置的论文图形（000 Figs. 2, 3, 5）渲染为 PNG

运行“attractor-cli &lt;command&gt; --help”查看某个命令的选项。
</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation type="vanished">导出对象的几何：将吸引子 F^k(X0) 导出为 PLY 点云（每个点附带最后作用的映射），将曲面对象经 k 轮经典细分后的控制网格导出为 OBJ 网格，或将网格对象细分 k 步后、每个顶点都置于其极限位置导出（OBJ）；或将其矩阵 S_i、M_i、A_i 导出为用于 JSR 工具箱的 MATLAB 元胞数组（matlab）。</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh) or matlab (matrices).</source>
        <translation type="vanished">ply（吸引子的点）、obj（细分网格）或 matlab（矩阵）。</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|matlab and --out FILE are required</source>
        <translation type="vanished">必须给出 --item NAME、--format ply|obj|matlab 和 --out FILE</translation>
    </message>
    <message>
        <source>--format must be ply, obj or matlab, got &apos;%1&apos;</source>
        <translation type="vanished">--format 必须是 ply、obj 或 matlab，得到的是“%1”</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); its maps as a Fractint .ifs entry (ifs); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation type="vanished">导出对象的几何：将吸引子 F^k(X0) 导出为 PLY 点云（每个点附带最后作用的映射），将曲面对象经 k 轮经典细分后的控制网格导出为 OBJ 网格，或将网格对象细分 k 步后、每个顶点都置于其极限位置导出（OBJ）；将其映射导出为 Fractint .ifs 条目（ifs）；或将其矩阵 S_i、M_i、A_i 导出为用于 JSR 工具箱的 MATLAB 元胞数组（matlab）。</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh), ifs (Fractint) or matlab (matrices).</source>
        <translation type="vanished">ply（吸引子的点）、obj（细分网格）、ifs（Fractint）或 matlab（矩阵）。</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|ifs|matlab and --out FILE are required</source>
        <translation type="vanished">必须给出 --item NAME、--format ply|obj|ifs|matlab 和 --out FILE</translation>
    </message>
    <message>
        <source>--format must be ply, obj, ifs or matlab, got &apos;%1&apos;</source>
        <translation type="vanished">--format 必须为 ply、obj、ifs 或 matlab，实际为“%1”</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit) as a fractal with control points.</source>
        <translation type="vanished">由其他工具的 IFS 文件创建项目：将 Fractint .ifs 文件（2D 和 3D，即 Fractint、xfractint 和 IFS Construction Kit 所用的格式）中的每个条目导入为带控制点的分形。</translation>
    </message>
    <message>
        <source>The file to import (.ifs).</source>
        <translation type="vanished">要导入的文件（.ifs）。</translation>
    </message>
    <message>
        <source>%1: import reads Fractint .ifs files</source>
        <translation type="vanished">%1：import 命令读取的是 Fractint .ifs 文件</translation>
    </message>
    <message>
        <source>%1: no entry could be imported</source>
        <translation>%1：未能导入任何条目</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n item(s): %2
</source>
        <translation>
            <numerusform>%1：%n 个对象：%2
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
        <translation type="vanished">用法：attractor-cli &lt;command&gt; [options]

命令：
  render     将项目中的某个对象渲染为 PNG、SVG 或 PDF
  animate    渲染对象动画的各帧（PNG 文件，MP4/GIF）
  analyse    特征值、压缩性、不动点、维数（JSON）
  points     以 CSV 格式输出 F^k(X0) 的点
  check      验证项目文件
  rewrite    加载项目并以规范形式重新保存
  export     点（PLY）、控制网格或网格（OBJ）、映射（.ifs）、矩阵（MATLAB）
  polygon    K 步细分后的控制多边形（JSON）
  import     将其他工具的 IFS 文件（Fractint .ifs）导入为项目
  import-mesh  将网格文件（OBJ、OFF、PLY）导入为含一个网格对象的项目
  valences   每个价的 lambda、mu 与 Reif 的 C1 判定（Catmull-Clark、Loop）
  examples   将内置的论文图形（000 Figs. 2, 3, 5）渲染为 PNG

运行“attractor-cli &lt;command&gt; --help”查看某个命令的选项。
</translation>
    </message>
    <message>
        <source>Export an item&apos;s geometry: the attractor F^k(X0) as a PLY point cloud (with the map applied last per point), a surface item&apos;s net after k rounds of classic subdivision as an OBJ mesh, or a mesh item after k steps with every vertex at its limit position (OBJ); its maps as a Fractint .ifs entry (ifs) or a flam3 genome that flam3-render draws in the frame of render&apos;s --size and --bounds (flame); or its matrices S_i, M_i, A_i as MATLAB cell arrays for the JSR toolbox (matlab).</source>
        <translation>导出项目的几何数据：吸引子 F^k(X0) 导出为 PLY 点云（每个点附带最后作用的映射），曲面项目经 k 轮经典细分后的控制网导出为 OBJ 网格，网格项目经 k 步细分、每个顶点置于其极限位置后导出（OBJ）；其映射导出为 Fractint .ifs 条目（ifs），或导出为 flam3 基因组，由 flam3-render 在 render 的 --size 和 --bounds 所定的画框中绘制（flame）；或将其矩阵 S_i、M_i、A_i 导出为供 JSR 工具箱使用的 MATLAB 元胞数组（matlab）。</translation>
    </message>
    <message>
        <source>ply (attractor points), obj (subdivided mesh), ifs (Fractint), flame (flam3) or matlab (matrices).</source>
        <translation>ply（吸引子点）、obj（细分网格）、ifs（Fractint）、flame（flam3）或 matlab（矩阵）。</translation>
    </message>
    <message>
        <source>--item NAME, --format ply|obj|ifs|flame|matlab and --out FILE are required</source>
        <translation type="vanished">必须指定 --item 名称、--format ply|obj|ifs|flame|matlab 和 --out 文件</translation>
    </message>
    <message>
        <source>--format must be ply, obj, ifs, flame or matlab, got &apos;%1&apos;</source>
        <translation>--format 必须是 ply、obj、ifs、flame 或 matlab，实际为“%1”</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has nothing to frame</source>
        <translation>“%1”没有可用于确定画框的内容</translation>
    </message>
    <message>
        <source>The output&apos;s format when its name has no suffix (e.g. /dev/stdout): png, svg, pdf or exr (default: the suffix).</source>
        <translation>输出名称没有后缀时（例如 /dev/stdout）使用的输出格式：png、svg、pdf 或 exr（默认：按后缀确定）。</translation>
    </message>
    <message>
        <source>PNG: 8 (the figure, default) or 16 (the attractor&apos;s raw density: alpha = log(1 + hits) / log(1 + most hits), the colour the hits&apos; mean; no title, polygons or margins). An .exr file always holds the raw density, as float32 counts.</source>
        <translation>PNG：8（图形，默认）或 16（吸引子的原始密度：alpha = log(1 + 命中数) / log(1 + 最大命中数)，颜色为各次命中的平均值；无标题、多边形和边距）。.exr 文件始终保存原始密度，为 float32 计数。</translation>
    </message>
    <message>
        <source>--format must be png, svg, pdf or exr, got &apos;%1&apos;</source>
        <translation>--format 必须是 png、svg、pdf 或 exr，实际为“%1”</translation>
    </message>
    <message>
        <source>--bits must be 8 or 16, got &apos;%1&apos;</source>
        <translation>--bits 必须是 8 或 16，实际为“%1”</translation>
    </message>
    <message>
        <source>--bits 16 writes PNG files, got &apos;%1&apos;</source>
        <translation type="vanished">--bits 16 只能写入 PNG 文件，实际为“%1”</translation>
    </message>
    <message>
        <source>the raw density (.exr, --bits 16) counts an attractor&apos;s points; this item&apos;s figure is a polygon</source>
        <translation type="vanished">原始密度（.exr，--bits 16）统计的是吸引子的点；此项目的图形是多边形</translation>
    </message>
    <message>
        <source>the raw density (.exr, --bits 16) is of attractors drawn in the plane; &apos;%1&apos; is drawn in space</source>
        <translation type="vanished">原始密度（.exr，--bits 16）仅适用于在平面中绘制的吸引子；“%1”在空间中绘制</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit), or every flame of a flam3 genome (.flame, .flam3: flam3, Apophysis, JWildfire), as a fractal with control points. Non-linear variations are dropped with a warning.</source>
        <translation type="vanished">将其他工具的 IFS 文件生成项目：Fractint .ifs 文件中的每个条目（2D 和 3D，即 Fractint、xfractint 和 IFS Construction Kit 的格式），或 flam3 基因组（.flame、.flam3：flam3、Apophysis、JWildfire）中的每个火焰分形，都会成为带控制点的分形。非线性变体将被舍弃并给出警告。</translation>
    </message>
    <message>
        <source>The file to import (.ifs, .flame, .flam3).</source>
        <translation>要导入的文件（.ifs、.flame、.flam3）。</translation>
    </message>
    <message>
        <source>%1: import reads Fractint .ifs and flam3 .flame (.flam3) files</source>
        <translation>%1：import 只读取 Fractint .ifs 和 flam3 .flame（.flam3）文件</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <source>Render an item&apos;s attractor (with its control polygons) to PNG, SVG or PDF; or its raw density (hits per pixel) to OpenEXR (.exr, float32 counts) or a 16-bit PNG (--bits 16), to tone-map elsewhere.</source>
        <translation>将项目的吸引子（连同其控制多边形）渲染为 PNG、SVG 或 PDF；或将其原始密度（每像素命中数）输出为 OpenEXR（.exr，float32 计数）或 16 位 PNG（--bits 16），以便在其他软件中进行色调映射。</translation>
    </message>
    <message>
        <source>Output file: .png, .svg, .pdf or .exr.</source>
        <translation>输出文件：.png、.svg、.pdf 或 .exr。</translation>
    </message>
    <message>
        <source>With --item: write the certificate of the curve&apos;s exact Hölder exponent (verify-regularity checks it).</source>
        <translation>配合 --item：写出该曲线精确 Hölder 指数的证书（由 verify-regularity 检验）。</translation>
    </message>
    <message>
        <source>--certificate needs --item: the certificate is one curve&apos;s</source>
        <translation>--certificate 需要 --item：证书属于单条曲线</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is not a subdivision curve: no regularity to certify</source>
        <translation>项 &apos;%1&apos; 不是细分曲线：没有可认证的正则性</translation>
    </message>
    <message>
        <source>Where a curve scheme is C^k as one of its parameters moves: the parameter intervals on which the certified Hölder exponent exceeds k, each end bracketed by bisection on certified values.</source>
        <translation>当曲线细分格式的某个参数变化时，确定其在何处为 C^k：即认证的 Hölder 指数大于 k 的参数区间，每个端点都通过对认证值进行二分来确定其所在区间。</translation>
    </message>
    <message>
        <source>The project file (.awb).</source>
        <translation>项目文件（.awb）。</translation>
    </message>
    <message>
        <source>The curve item (default: the first item with an attractor).</source>
        <translation>曲线项（默认：第一个带吸引子的项）。</translation>
    </message>
    <message>
        <source>omega (four-point), a or b (corner cutting).</source>
        <translation type="vanished">omega（四点格式），a 或 b（切角格式）。</translation>
    </message>
    <message>
        <source>The start of the range.</source>
        <translation>范围的起点。</translation>
    </message>
    <message>
        <source>The end of the range.</source>
        <translation>范围的终点。</translation>
    </message>
    <message>
        <source>k: the class C^k asked for (default 1).</source>
        <translation>k：所要求的光滑类 C^k（默认 1）。</translation>
    </message>
    <message>
        <source>Values of the first sweep, 2 to 10000 (default 24).</source>
        <translation>第一轮扫描的取值个数，2 到 10000（默认 24）。</translation>
    </message>
    <message>
        <source>Bracket width at which bisection stops (default 1e-6).</source>
        <translation>二分停止时的区间宽度（默认 1e-6）。</translation>
    </message>
    <message>
        <source>Seconds of joint spectral radius per value (default 0.3).</source>
        <translation>每个取值计算联合谱半径所用的秒数（默认 0.3）。</translation>
    </message>
    <message>
        <source>Print JSON instead of text.</source>
        <translation>输出 JSON 而非文本。</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; is not a subdivision curve: its scheme has no parameter to move</source>
        <translation>项 &apos;%1&apos; 不是细分曲线：其格式没有可变动的参数</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no parameter &apos;%3&apos;: omega belongs to the four-point scheme, a and b to corner cutting</source>
        <translation type="vanished">项 &apos;%1&apos;（%2）没有参数 &apos;%3&apos;：omega 属于四点格式，a 和 b 属于切角格式</translation>
    </message>
    <message>
        <source>--from and --to are required</source>
        <translation>必须指定 --from 和 --to</translation>
    </message>
    <message>
        <source>%1: C^%2 for %3 in %4 interval(s) of [%5, %6]</source>
        <translation>%1：当 %3 位于 [%5, %6] 中的 %4 个区间内时为 C^%2</translation>
    </message>
    <message>
        <source>%1 (the range&apos;s end)</source>
        <translation>%1（范围终点）</translation>
    </message>
    <message>
        <source>in [%1, %2]%3</source>
        <translation>位于 [%1, %2] 内%3</translation>
    </message>
    <message>
        <source> (the bounds cannot decide beyond)</source>
        <translation>（超出此范围，界无法判定）</translation>
    </message>
    <message>
        <source>  from %1 to %2</source>
        <translation>  从 %1 到 %2</translation>
    </message>
    <message>
        <source>%1 evaluations, %2 s</source>
        <translation>%1 次求值，%2 秒</translation>
    </message>
    <message>
        <source>Re-check the certificate of an exact Hölder exponent, independently of the search that found it.</source>
        <translation>独立于找到精确 Hölder 指数的那次搜索，重新检验其证书。</translation>
    </message>
    <message>
        <source>The certificate (.json).</source>
        <translation>证书（.json）。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1: larger than 64 MiB, not a certificate</source>
        <translation>%1：大于 64 MiB，不是证书</translation>
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
        <translation type="vanished">用法：attractor-cli &lt;command&gt; [options]

命令：
  render     将项目中的一个项渲染为 PNG、SVG 或 PDF
  animate    渲染一个项的动画帧（PNG 文件、MP4/GIF）
  analyse    特征值、压缩性、不动点、维数（JSON）
  points     以 CSV 格式输出 F^k(X0) 的点
  check      验证项目文件
  rewrite    加载项目并以规范形式保存
  export     点（PLY）、网或网格（OBJ）、映射（.ifs）、矩阵（MATLAB）
  polygon    K 步细分后的控制多边形（JSON）
  import     将其他工具的 IFS 文件（Fractint .ifs）导入为项目
  import-mesh  将网格文件（OBJ、OFF、PLY）导入为带网格项的项目
  valences   每个价的 lambda、mu 及 Reif 的 C1 判定（Catmull-Clark、Loop）
  regularity-interval  参数变化时格式在何处为 C^k
  verify-regularity  重新检验精确 Hölder 指数的证书
  examples   将内置的论文插图（000 Figs. 2, 3, 5）渲染为 PNG

运行 &apos;attractor-cli &lt;command&gt; --help&apos; 查看某个命令的选项。
</translation>
    </message>
    <message>
        <source>omega (four-point), a or b (corner cutting), or the name used in --mask.</source>
        <translation>omega（四点格式）、a 或 b（切角），或 --mask 中使用的名称。</translation>
    </message>
    <message>
        <source>For a mask item: its coefficients with the parameter in them, e.g. &quot;-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w&quot;.</source>
        <translation>对于掩模对象：其系数中含有该参数，例如 &quot;-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w&quot;。</translation>
    </message>
    <message>
        <source>--mask needs a mask item; &apos;%1&apos; is %2</source>
        <translation type="vanished">--mask 需要一个掩模对象；&apos;%1&apos; 是 %2</translation>
    </message>
    <message>
        <source>the parameter of --mask must be a name that is not a function or constant (pi, e, sqrt, ...), got &apos;%1&apos;</source>
        <translation type="vanished">--mask 的参数必须是一个不是函数或常数（pi、e、sqrt 等）的名称，得到 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the mask &apos;%1&apos; does not contain the parameter &apos;%2&apos;</source>
        <translation type="vanished">掩模 &apos;%1&apos; 不包含参数 &apos;%2&apos;</translation>
    </message>
    <message>
        <source>item &apos;%1&apos; (%2) has no parameter &apos;%3&apos;: omega belongs to the four-point scheme, a and b to corner cutting; a mask item takes --mask with the parameter in its coefficients</source>
        <translation type="vanished">对象 &apos;%1&apos;（%2）没有参数 &apos;%3&apos;：omega 属于四点格式，a 和 b 属于切角；掩模对象使用 --mask 并在其系数中写入参数</translation>
    </message>
    <message>
        <source>the rendering was cancelled</source>
        <translation type="vanished">渲染已取消</translation>
    </message>
    <message>
        <source>the project has no items</source>
        <translation>项目中没有对象</translation>
    </message>
    <message>
        <source>no item called &quot;%1&quot;; the items: %2</source>
        <translation>没有名为“%1”的对象；现有对象：%2</translation>
    </message>
    <message>
        <source>Set properties of an item and save the project (atomically: all of them or none), or list them. A value is typed as in the Properties dock: a number (3/8 and sqrt(3) too), a choice by its number, its word in the file or its text, true or false, a complex number as 0.5,0.3 or 0.5+0.3i; a structured value (points, matrices, a list) as JSON.</source>
        <translation>设置对象的属性并保存项目（原子操作：要么全部设置，要么全不设置），或列出这些属性。值的写法与“属性”面板中相同：数（也可以是 3/8 和 sqrt(3)）；选项可用其编号、其在文件中的单词或其显示文本；true 或 false；复数写作 0.5,0.3 或 0.5+0.3i；结构化的值（点、矩阵、列表）写作 JSON。</translation>
    </message>
    <message>
        <source>Properties to set, in order.</source>
        <translation>要设置的属性，按顺序设置。</translation>
    </message>
    <message>
        <source>The item (default: the first).</source>
        <translation>对象（默认：第一个）。</translation>
    </message>
    <message>
        <source>List the item&apos;s properties: key, type, value, range and choices.</source>
        <translation>列出对象的属性：键、类型、值、范围和可选项。</translation>
    </message>
    <message>
        <source>With --list: as JSON.</source>
        <translation>配合 --list：以 JSON 格式输出。</translation>
    </message>
    <message>
        <source>expected a project file; see --help</source>
        <translation>应提供项目文件；参见 --help</translation>
    </message>
    <message>
        <source>--list takes no key=value</source>
        <translation>--list 不接受 key=value</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>(shown, not set)</source>
        <translation>（仅显示，不可设置）</translation>
    </message>
    <message>
        <source>nothing to set: give key=value (or --list)</source>
        <translation>没有要设置的内容：请给出 key=value（或 --list）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not key=value</source>
        <translation>“%1”不是 key=value 形式</translation>
    </message>
    <message>
        <source>render an item of a project to PNG, SVG or PDF</source>
        <translation>将项目中的一个项渲染为 PNG、SVG 或 PDF</translation>
    </message>
    <message>
        <source>render the frames of an item&apos;s animation (PNG files, MP4/GIF)</source>
        <translation>渲染一个项的动画帧（PNG 文件、MP4/GIF）</translation>
    </message>
    <message>
        <source>eigenvalues, contractivity, fixed points, dimension (JSON)</source>
        <translation>特征值、压缩性、不动点、维数（JSON）</translation>
    </message>
    <message>
        <source>the points of F^k(X0) as CSV</source>
        <translation>以 CSV 格式输出 F^k(X0) 的点</translation>
    </message>
    <message>
        <source>set an item&apos;s properties and save, or list them</source>
        <translation>设置对象的属性并保存，或列出这些属性</translation>
    </message>
    <message>
        <source>validate a project file</source>
        <translation>验证项目文件</translation>
    </message>
    <message>
        <source>load and save a project in canonical form</source>
        <translation>加载项目并以规范形式保存</translation>
    </message>
    <message>
        <source>points (PLY), a net or mesh (OBJ), maps (.ifs), matrices (MATLAB)</source>
        <translation>点（PLY）、网或网格（OBJ）、映射（.ifs）、矩阵（MATLAB）</translation>
    </message>
    <message>
        <source>the control polygon after K subdivision steps (JSON)</source>
        <translation>K 步细分后的控制多边形（JSON）</translation>
    </message>
    <message>
        <source>another tool&apos;s IFS file (Fractint .ifs) as a project</source>
        <translation>将其他工具的 IFS 文件（Fractint .ifs）导入为项目</translation>
    </message>
    <message>
        <source>a mesh file (OBJ, OFF, PLY) as a project with a mesh item</source>
        <translation>将网格文件（OBJ、OFF、PLY）导入为带网格项的项目</translation>
    </message>
    <message>
        <source>lambda, mu, Reif&apos;s C1 verdict per valence (Catmull-Clark, Loop)</source>
        <translation>每个价的 lambda、mu 及 Reif 的 C1 判定（Catmull-Clark、Loop）</translation>
    </message>
    <message>
        <source>where a scheme is C^k as a parameter moves</source>
        <translation>参数变化时格式在何处为 C^k</translation>
    </message>
    <message>
        <source>re-check the certificate of an exact Hölder exponent</source>
        <translation>重新检验精确 Hölder 指数的证书</translation>
    </message>
    <message>
        <source>render the built-in paper figures (000 Figs. 2, 3, 5) to PNG</source>
        <translation>将内置的论文插图（000 Figs. 2, 3, 5）渲染为 PNG</translation>
    </message>
    <message>
        <source>Usage: attractor-cli &lt;command&gt; [options]</source>
        <translation>用法：attractor-cli &lt;command&gt; [options]</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>命令：</translation>
    </message>
    <message>
        <source>Run &apos;attractor-cli &lt;command&gt; --help&apos; for the options of a command.</source>
        <translation>运行 &apos;attractor-cli &lt;command&gt; --help&apos; 查看某个命令的选项。</translation>
    </message>
    <message>
        <source>%1: its %2 entries make a project of %3 MB, more than the %4 MB a project file may be</source>
        <translation>%1：其 %2 个条目构成 %3 MB 的项目，超过项目文件允许的 %4 MB</translation>
    </message>
    <message>
        <source>%1: %2: note: its chaos game does not contract on average (the Lyapunov exponent along its orbit is %3): flam3 draws it by discarding the points that escape</source>
        <translation>%1：%2：注意：其混沌游戏平均而言不收缩（沿其轨道的李雅普诺夫指数为 %3）：flam3 通过丢弃逃逸的点来绘制它</translation>
    </message>
    <message>
        <source>Make a project of another tool&apos;s IFS file: every entry of a Fractint .ifs file (2D and 3D, the format of Fractint, xfractint and the IFS Construction Kit), or every flame of a flam3 genome (.flame, .flam3: flam3, Apophysis, JWildfire): a flame of affine maps as a fractal with control points, any other as a fractal flame item drawn by flam3&apos;s chaos game (a variation this program does not know is named in a warning).</source>
        <translation>由其他工具的 IFS 文件创建项目：Fractint .ifs 文件中的每个条目（2D 和 3D，即 Fractint、xfractint 和 IFS Construction Kit 所用的格式），或 flam3 基因组（.flame、.flam3：flam3、Apophysis、JWildfire）中的每个火焰：由仿射映射构成的火焰导入为带控制点的分形，其他火焰导入为由 flam3 的混沌游戏绘制的分形火焰对象（本程序不认识的变体会在警告中列出其名称）。</translation>
    </message>
    <message>
        <source>attractor-cli: note: all %1 faces are triangles; --scheme loop keeps them triangles (Catmull-Clark makes each one three quads around a new valence-3 vertex)</source>
        <translation>attractor-cli：注意：全部 %1 个面都是三角形；--scheme loop 会保持其为三角形（Catmull-Clark 会把每个面变成围绕一个新的 3 价顶点的三个四边形）</translation>
    </message>
    <message>
        <source>A complex Bézier curve of t = 1/2 + iy in the scaled coordinates g(z, 1/(2y)) of 004 Thm 3.7.3, where it approaches the Takagi graph (the item&apos;s &quot;scaled&quot;, for this figure)</source>
        <translation>t = 1/2 + iy 时的复 Bézier 曲线，采用 004 Thm 3.7.3 的缩放坐标 g(z, 1/(2y))，在该坐标下它趋近高木函数图像（即此图中该项的 &quot;scaled&quot;）</translation>
    </message>
    <message>
        <source>--scaled draws a complex Bézier curve of t = 1/2 + iy (y ≠ 0) with control points on the real axis; &apos;%1&apos; is not one</source>
        <translation>--scaled 绘制 t = 1/2 + iy（y ≠ 0）且控制点位于实轴上的复 Bézier 曲线；&apos;%1&apos; 不是这样的曲线</translation>
    </message>
    <message>
        <source>attractor-cli: warning: %1</source>
        <translation>attractor-cli：警告：%1</translation>
    </message>
    <message>
        <source>  sharp features: %1 creases, %2 corners, %3 holes; boundary %4, crease method %5, triangles %6
</source>
        <translation>  尖锐特征：%1 条折痕，%2 个角点，%3 个孔洞；边界 %4，折痕方法 %5，三角形 %6
</translation>
    </message>
    <message>
        <source>Repair what is well defined before the checks: weld boundary vertices at the same position, turn flipped faces over, split vertices whose faces form several fans, name repeated vertices once; say each change.</source>
        <translation type="vanished">在检查之前修复明确定义的问题：焊接位置相同的边界顶点，翻转反向的面，拆分其面构成多个扇形的顶点，重复的顶点只保留一次；逐条说明每个更改。</translation>
    </message>
    <message>
        <source>repaired: %1</source>
        <translation>已修复：%1</translation>
    </message>
    <message>
        <source>attractor-cli: not repaired: %1</source>
        <translation>attractor-cli：未修复：%1</translation>
    </message>
    <message>
        <source>repaired: nothing needed repair</source>
        <translation>已修复：无需修复</translation>
    </message>
    <message>
        <source> (--repair would weld %1 vertices, turn %2 faces over and split %3 vertices)</source>
        <translation type="vanished">（--repair 将焊接 %1 个顶点，翻转 %2 个面并拆分 %3 个顶点）</translation>
    </message>
    <message>
        <source>name repeated vertices once in %1 faces</source>
        <translation>在 %1 个面中将重复的顶点只保留一次</translation>
    </message>
    <message>
        <source>weld %1 vertices</source>
        <translation>焊接 %1 个顶点</translation>
    </message>
    <message>
        <source>turn %1 faces over</source>
        <translation>翻转 %1 个面</translation>
    </message>
    <message>
        <source>split %1 vertices</source>
        <translation>拆分 %1 个顶点</translation>
    </message>
    <message>
        <source> (--repair would %1)</source>
        <translation>（--repair 将会：%1）</translation>
    </message>
    <message>
        <source>Make a project of a mesh file (OBJ, OFF, PLY ASCII or binary): one subdivision-mesh item with the file&apos;s vertices, in its numbering, and its polygons. A non-manifold mesh (edges of three or more faces, faces of opposite orientations, vertices whose faces form several fans) is drawn as OpenSubdiv draws it, with a note.</source>
        <translation>由网格文件（OBJ、OFF、ASCII 或二进制 PLY）创建项目：一个细分网格项，包含文件的顶点（保持其编号）和多边形。非流形网格（三个或更多面共享的边、方向相反的面、其面形成多个扇形的顶点）按 OpenSubdiv 的方式绘制，并附注说明。</translation>
    </message>
    <message>
        <source>Repair what is well defined before the checks: weld boundary vertices at the same position, turn flipped faces over, split vertices whose faces form several fans, name repeated vertices once; say each change (the mesh is then drawn as the repaired surface, not as OpenSubdiv draws the original).</source>
        <translation>在检查之前修复明确定义的问题：焊接位置相同的边界顶点，翻转朝向相反的面，拆分其面形成多个扇形的顶点，重复的顶点只列一次；说明每处修改（此后网格按修复后的曲面绘制，而不是按 OpenSubdiv 绘制原网格的方式）。</translation>
    </message>
    <message>
        <source>attractor-cli: note: the mesh is %1%2</source>
        <translation>attractor-cli: 注意：该网格为%1%2</translation>
    </message>
    <message>
        <source>… (%1 in all)</source>
        <translation>……（共 %1 个）</translation>
    </message>
    <message>
        <source>--item NAME is required: %1 has %2 items with an attractor: %3</source>
        <translation>需要 --item 名称：%1 有 %2 个带吸引子的对象：%3</translation>
    </message>
    <message>
        <source>The item (needed when the project has several).</source>
        <translation>对象（项目有多个对象时必需）。</translation>
    </message>
    <message>
        <source>--format ply|obj|ifs|flame|matlab and --out FILE are required</source>
        <translation>需要 --format ply|obj|ifs|flame|matlab 和 --out 文件</translation>
    </message>
    <message>
        <source>Start set: point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:... (plane coordinates; x,y,z for a surface) | lifted:x,y,c1,...;x,y,c1,... (points of the lifted space of 000 §2) | net:i,j,... (control points by index, from 0: the rows of the lifted P) | vertex-limits (a mesh item: the limit positions of the vertices of the mesh refined k times; default: the item&apos;s).</source>
        <translation>初始集：point:x,y | segment:x1,y1,x2,y2 | triangle:... | polygon:... | points:...（平面坐标；曲面为 x,y,z）| lifted:x,y,c1,...;x,y,c1,...（000 §2 提升空间中的点）| net:i,j,...（按索引选取的控制点，从 0 开始：提升矩阵 P 的行）| vertex-limits（网格对象：网格细化 k 次后各顶点的极限位置；默认：对象自身的初始集）。</translation>
    </message>
    <message>
        <source>%1: %2 % (%3 s</source>
        <translation>%1：%2 %（%3 秒</translation>
    </message>
    <message>
        <source>, about %1 s left</source>
        <translation>，约剩 %1 秒</translation>
    </message>
    <message>
        <source>Report the iteration&apos;s progress on stderr, one line per report (default: on a terminal only, after a second).</source>
        <translation>在 stderr 上报告迭代进度，每次报告一行（默认：仅在终端上，一秒之后）。</translation>
    </message>
</context>
<context>
    <name>awb::core</name>
    <message>
        <source>%1: entry (row %2, column %3) is not a finite number</source>
        <translation>%1：元素（第 %2 行，第 %3 列）不是有限数</translation>
    </message>
    <message>
        <source>matrix rows of different lengths</source>
        <translation>矩阵各行长度不同</translation>
    </message>
</context>
<context>
    <name>awb::exchange</name>
    <message>
        <source>%1, line %2, column %3</source>
        <translation>%1，第 %2 行，第 %3 列</translation>
    </message>
    <message>
        <source>: entry %1</source>
        <translation>：条目 %1</translation>
    </message>
    <message>
        <source>a &apos;}&apos; without its &apos;{&apos;</source>
        <translation>“}”没有与之配对的“{”</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not followed by &apos;{&apos;: an entry is NAME { rows }</source>
        <translation>“%1”后面没有“{”：条目的格式为 NAME { rows }</translation>
    </message>
    <message>
        <source>entry at line %1</source>
        <translation>第 %1 行的条目</translation>
    </message>
    <message>
        <source>a &apos;{&apos; inside an entry: its &apos;}&apos; is missing</source>
        <translation>条目内出现“{”：该条目缺少“}”</translation>
    </message>
    <message>
        <source>the file ends before the entry&apos;s &apos;}&apos;</source>
        <translation>文件在条目的“}”之前就结束了</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a finite number</source>
        <translation>“%1”不是有限数</translation>
    </message>
    <message>
        <source>the entry has no maps</source>
        <translation>该条目没有映射</translation>
    </message>
    <message>
        <source>%1 numbers: a %2D entry has rows of %3 (the map&apos;s coefficients, then its probability), %4 left over</source>
        <translation>共 %1 个数：%2D 条目每行 %3 个数（先是映射的系数，然后是其概率），多出 %4 个</translation>
    </message>
    <message>
        <source>map %1 has the negative probability %2</source>
        <translation>映射 %1 的概率 %2 为负</translation>
    </message>
    <message>
        <source>a Fractint entry holds maps of the plane or of space, not of dimension %1</source>
        <translation>Fractint 条目只包含平面或空间中的映射，而不包含 %1 维的映射</translation>
    </message>
    <message>
        <source>the entry&apos;s maps are not all of its dimension</source>
        <translation>该条目的映射并非都与条目同维</translation>
    </message>
    <message>
        <source>entry %1: random iteration leaves every bound (its maps do not contract)</source>
        <translation>条目 %1：随机迭代超出了所有界限（其映射不是压缩映射）</translation>
    </message>
    <message>
        <source>the row starting here runs on to the next line: a %1D entry has rows of %2 numbers (the map&apos;s coefficients, then its probability), one row per line</source>
        <translation>从此处开始的一行延续到了下一行：%1D 条目每行有 %2 个数（映射的系数，然后是其概率），每行一个映射</translation>
    </message>
    <message>
        <source>%1 maps: at most %2 maps are supported</source>
        <translation>%1 个映射：最多支持 %2 个映射</translation>
    </message>
    <message>
        <source>the probabilities sum to %1, not 1: they are used as relative weights</source>
        <translation>概率之和为 %1 而非 1：将作为相对权重使用</translation>
    </message>
    <message>
        <source>the probabilities are all 0: the maps are chosen with equal probabilities</source>
        <translation>概率全为 0：各映射以相等概率选取</translation>
    </message>
    <message>
        <source>a file of bare rows (Fractint 10 and 15: one IFS, no NAME { }) has rows of 7 (2D) or 13 (3D) numbers, its first line %1</source>
        <translation>裸行文件（Fractint 10 和 15：单个 IFS，没有 NAME { }）每行有 7 个（2D）或 13 个（3D）数，其第一行为 %1 个</translation>
    </message>
    <message>
        <source>a file of bare rows (Fractint 10 and 15) has no braces: an entry is NAME { rows } throughout</source>
        <translation>裸行文件（Fractint 10 和 15）不含花括号：否则每个条目都应为 NAME { 行 }</translation>
    </message>
    <message>
        <source>%1 more problems</source>
        <translation>另有 %1 个问题</translation>
    </message>
    <message>
        <source>%1 more entries after the first %2: one file gives at most %2</source>
        <translation>前 %2 个之后还有 %1 个条目：一个文件最多提供 %2 个</translation>
    </message>
    <message>
        <source>%1 more warnings</source>
        <translation>另有 %1 个警告</translation>
    </message>
</context>
<context>
    <name>awb::flame</name>
    <message>
        <source>%1: a coefficient is not a finite number</source>
        <translation>%1：某个系数不是有限数</translation>
    </message>
    <message>
        <source>%1: variation %2 does not exist</source>
        <translation>%1：变体 %2 不存在</translation>
    </message>
    <message>
        <source>%1: the weight of variation %2 is not a finite number</source>
        <translation>%1：变体 %2 的权重不是有限数</translation>
    </message>
    <message>
        <source>%1: its variation parameters are incomplete</source>
        <translation>%1：其变体参数不完整</translation>
    </message>
    <message>
        <source>%1: parameter %2 is not a finite number</source>
        <translation>%1：参数 %2 不是有限数</translation>
    </message>
    <message>
        <source>%1: its colour, colour speed or opacity is not a finite number</source>
        <translation>%1：其颜色、颜色速度或不透明度不是有限数</translation>
    </message>
    <message>
        <source>the flame has no xform</source>
        <translation>火焰没有 xform</translation>
    </message>
    <message>
        <source>the flame has %1 xforms; at most %2 are drawn</source>
        <translation>火焰有 %1 个 xform；最多绘制 %2 个</translation>
    </message>
    <message>
        <source>xform %1</source>
        <translation>xform %1</translation>
    </message>
    <message>
        <source>%1: its weight %2 is not a number &gt;= 0</source>
        <translation>%1：其权重 %2 不是 &gt;= 0 的数</translation>
    </message>
    <message>
        <source>%1: its xaos row has %2 entries for %3 xforms</source>
        <translation>%1：其 xaos 行有 %2 项，而 xform 有 %3 个</translation>
    </message>
    <message>
        <source>%1: a xaos entry is not a number &gt;= 0</source>
        <translation>%1：某个 xaos 项不是 &gt;= 0 的数</translation>
    </message>
    <message>
        <source>every xform of the flame has weight 0: none is ever chosen</source>
        <translation>火焰的每个 xform 权重都为 0：没有任何一个会被选中</translation>
    </message>
    <message>
        <source>xform %1: its xaos row forbids every xform, so an orbit that reaches it cannot go on</source>
        <translation>xform %1：其 xaos 行禁止所有 xform，因此到达它的轨道无法继续</translation>
    </message>
    <message>
        <source>the final xform</source>
        <translation>最终 xform</translation>
    </message>
    <message>
        <source>there is no flame to draw</source>
        <translation>没有要绘制的火焰</translation>
    </message>
    <message>
        <source>the spatial filter of radius %1 at supersample %2 would be %3 cells wide; at most %4</source>
        <translation>半径 %1、超采样 %2 的空间滤波器宽 %3 个单元；最多 %4</translation>
    </message>
    <message>
        <source>the spatial filter of radius %1 is too small</source>
        <translation>半径 %1 的空间滤波器太小</translation>
    </message>
    <message>
        <source>the estimator curve must be &gt; 0</source>
        <translation>估计器曲线必须 &gt; 0</translation>
    </message>
    <message>
        <source>the estimator radius %1 must be at least its minimum %2 (and not negative)</source>
        <translation>估计器半径 %1 必须不小于其最小值 %2（且非负）</translation>
    </message>
    <message>
        <source>the estimator (radius %1, minimum %2, curve %3) needs too many kernels (%4)</source>
        <translation>估计器（半径 %1，最小值 %2，曲线 %3）需要的核太多（%4）</translation>
    </message>
    <message>
        <source>the estimator of radius %1 at supersample %2 needs %3 coefficients; at most %4</source>
        <translation>半径 %1、超采样 %2 的估计器需要 %3 个系数；最多 %4</translation>
    </message>
    <message>
        <source>a %1 x %2 picture of the flame at supersample %3 needs %4 x %5 histogram cells; at most 32768 a side</source>
        <translation>超采样 %3 下 %1 x %2 的火焰图像需要 %4 x %5 个直方图单元；每边最多 32768</translation>
    </message>
    <message>
        <source>a %1 x %2 picture of the flame at supersample %3 needs %4 MB of histograms; at most %5 MB</source>
        <translation>超采样 %3 下 %1 x %2 的火焰图像需要 %4 MB 直方图；最多 %5 MB</translation>
    </message>
    <message>
        <source>the flame&apos;s passes is %1; it takes 1 to %2</source>
        <translation>火焰的遍数为 %1；允许 1 到 %2</translation>
    </message>
</context>
<context>
    <name>awb::flame::MakeSink</name>
    <message>
        <source>there is no flame to draw</source>
        <translation>没有要绘制的火焰</translation>
    </message>
</context>
<context>
    <name>awb::ifs</name>
    <message>
        <source>the IFS has 1 map (0)</source>
        <translation>该 IFS 有 1 个映射（0）</translation>
    </message>
    <message>
        <source>the IFS has %1 maps (0..%2)</source>
        <translation>该 IFS 有 %1 个映射（0..%2）</translation>
    </message>
    <message>
        <source>no parameter intervals</source>
        <translation>没有参数区间</translation>
    </message>
    <message>
        <source>a parameter interval is empty or not finite</source>
        <translation>某个参数区间为空或不是有限的</translation>
    </message>
    <message>
        <source>the address has %1 symbols, more than %2</source>
        <translation>该地址有 %1 个符号，超过了 %2 个</translation>
    </message>
    <message>
        <source>symbol %1 of the address is map %2, but %3</source>
        <translation>地址的第 %1 个符号是映射 %2，但%3</translation>
    </message>
    <message>
        <source>the IFS has no maps</source>
        <translation>该 IFS 没有映射</translation>
    </message>
    <message>
        <source>the address &apos;%1&apos; has an empty symbol (a comma too many)</source>
        <translation>地址“%1”含有空符号（多了一个逗号）</translation>
    </message>
    <message>
        <source>the address &apos;%1&apos; ends with a comma</source>
        <translation>地址“%1”以逗号结尾</translation>
    </message>
    <message>
        <source>the address is empty: give map numbers such as 0,1,1</source>
        <translation>地址为空：请给出映射编号，例如 0,1,1</translation>
    </message>
    <message>
        <source>symbol %1 of the address, &apos;%2&apos;, is not a map number (0-based whole number)</source>
        <translation>地址的第 %1 个符号“%2”不是映射编号（从 0 开始的整数）</translation>
    </message>
    <message>
        <source>no subdivision matrices</source>
        <translation>没有细分矩阵</translation>
    </message>
    <message>
        <source>the subdivision matrices differ in size</source>
        <translation>各细分矩阵的尺寸不同</translation>
    </message>
    <message>
        <source>the parameter %1 is outside [0, 1]</source>
        <translation>参数 %1 不在 [0, 1] 内</translation>
    </message>
    <message>
        <source>an address has 0..%1 symbols</source>
        <translation>地址的符号数为 0..%1</translation>
    </message>
    <message>
        <source>the parameter interval must satisfy 0 &lt;= t0 &lt; t1 &lt;= 1</source>
        <translation>参数区间必须满足 0 &lt;= t0 &lt; t1 &lt;= 1</translation>
    </message>
    <message>
        <source>the seed point has %1 coordinates, the IFS %2</source>
        <translation>种子点有 %1 个坐标，而该 IFS 有 %2 个</translation>
    </message>
    <message>
        <source>map 0 does not converge to a fixed point</source>
        <translation>映射 0 不收敛到不动点</translation>
    </message>
    <message>
        <source>iteration depth must be between 0 and %1, got %2</source>
        <translation>迭代深度必须介于 0 和 %1 之间，实际为 %2</translation>
    </message>
    <message>
        <source>the start set is empty</source>
        <translation>初始集为空</translation>
    </message>
    <message>
        <source>start set has %1 coordinates, the IFS space has %2</source>
        <translation>初始集有 %1 个坐标，而 IFS 空间有 %2 个</translation>
    </message>
    <message>
        <source>start set</source>
        <translation>初始集</translation>
    </message>
    <message>
        <source>at most 255 maps are supported, got %1</source>
        <translation type="vanished">最多支持 255 个映射，实际为 %1 个</translation>
    </message>
    <message>
        <source>no sink to receive the attractor</source>
        <translation>没有用于接收吸引子的接收器</translation>
    </message>
    <message>
        <source>start point has %1 coordinates, the IFS space has %2</source>
        <translation>初始点有 %1 个坐标，而 IFS 空间有 %2 个</translation>
    </message>
    <message>
        <source>start point</source>
        <translation>初始点</translation>
    </message>
    <message>
        <source>at most %1 random-iteration samples, got %2</source>
        <translation>随机迭代的样本数最多为 %1，实际为 %2</translation>
    </message>
    <message>
        <source>column %1 of %2 sums to %3, not 1: it does not map barycentric points to barycentric points</source>
        <translation>%2 的第 %1 列之和为 %3，而不是 1：它不能把重心坐标点映射为重心坐标点</translation>
    </message>
    <message>
        <source>the BCIFS has no cell &apos;%1&apos;</source>
        <translation>该 BCIFS 没有单元“%1”</translation>
    </message>
    <message>
        <source>the BCIFS has no operator &apos;%1&apos;</source>
        <translation>该 BCIFS 没有算子“%1”</translation>
    </message>
    <message>
        <source>the BCIFS has no cells</source>
        <translation>该 BCIFS 没有单元</translation>
    </message>
    <message>
        <source>cell &apos;%1&apos; has dimension %2; it needs at least one control point</source>
        <translation>单元“%1”的维数为 %2；它至少需要一个控制点</translation>
    </message>
    <message>
        <source>operator &apos;%1&apos; joins a cell that does not exist</source>
        <translation>算子“%1”连接了一个不存在的单元</translation>
    </message>
    <message>
        <source>operator &apos;%1&apos; (%2 -&gt; %3)</source>
        <translation>算子“%1”（%2 -&gt; %3）</translation>
    </message>
    <message>
        <source>%1 joins cells of the wrong kinds: subdivisions join edges or vertices, boundary operators go from an edge to a vertex, placements from the model</source>
        <translation>%1 连接的单元类型不正确：细分算子连接边或顶点，边界算子从边指向顶点，放置算子从模型出发</translation>
    </message>
    <message>
        <source>%1 is %2; it must be %3 x %4 (column convention: rows = dimension of &apos;%5&apos;, columns = dimension of &apos;%6&apos;)</source>
        <translation>%1 的尺寸为 %2；它必须为 %3 x %4（列约定：行数 = “%5”的维数，列数 = “%6”的维数）</translation>
    </message>
    <message>
        <source>edge cell &apos;%1&apos; has no subdivision operator: its attractor would be empty</source>
        <translation>边单元“%1”没有细分算子：其吸引子将为空</translation>
    </message>
    <message>
        <source>constraint %1</source>
        <translation>约束 %1</translation>
    </message>
    <message>
        <source>%1 has an empty side or an unknown operator</source>
        <translation>%1 有一侧为空，或含有未知算子</translation>
    </message>
    <message>
        <source>%1: %2 ends at &apos;%3&apos; but %4 starts at &apos;%5&apos;</source>
        <translation>%1：%2 终止于“%3”，但 %4 起始于“%5”</translation>
    </message>
    <message>
        <source>%1 (%2) compares paths between different cells</source>
        <translation>%1（%2）比较的是不同单元之间的路径</translation>
    </message>
    <message>
        <source>%1 constraint %2 %3 is violated by %4 (entry row %5, column %6)</source>
        <translation>%1 约束 %2 %3 不满足，偏差为 %4（位于第 %5 行第 %6 列的元素）</translation>
    </message>
    <message>
        <source>; also violated:</source>
        <translation>；同样不满足的还有：</translation>
    </message>
    <message>
        <source>edge cell &apos;%1&apos; has no placement (control points): it cannot be drawn</source>
        <translation>边单元“%1”没有放置（控制点）：无法绘制</translation>
    </message>
    <message>
        <source>the junction matrix must be square and at least 2 x 2, got %1</source>
        <translation>拼接矩阵必须是至少 2 x 2 的方阵，实际为 %1</translation>
    </message>
    <message>
        <source>the copy&apos;s placement must have %1 rows (one per control point of the junction), got %2</source>
        <translation>副本的放置必须有 %1 行（拼接的每个控制点一行），实际为 %2 行</translation>
    </message>
    <message>
        <source>the junction has %1 control points, got %2</source>
        <translation>该拼接有 %1 个控制点，实际给出 %2 个</translation>
    </message>
    <message>
        <source>junction matrix</source>
        <translation>拼接矩阵</translation>
    </message>
    <message>
        <source>copy placement</source>
        <translation>副本放置</translation>
    </message>
    <message>
        <source>the junction matrix</source>
        <translation>拼接矩阵</translation>
    </message>
    <message>
        <source>the copy placement</source>
        <translation>副本放置</translation>
    </message>
    <message>
        <source>the copies collapse onto the fixed point: no tangent information</source>
        <translation>各副本坍缩到不动点上：没有切线信息</translation>
    </message>
    <message>
        <source>lambda = %1: %2</source>
        <translation>lambda = %1：%2</translation>
    </message>
    <message>
        <source>; |lambda| &gt;= 1, so the junction matrix does not contract</source>
        <translation>；|lambda| &gt;= 1，因此拼接矩阵不压缩</translation>
    </message>
    <message>
        <source> (the copy has no component along the subdominant eigenvector, lambda = %1, so the next eigenvalue governs)</source>
        <translation> （副本在次占优特征向量方向上没有分量，lambda = %1，因此由下一个特征值决定）</translation>
    </message>
    <message>
        <source> (the eigenvectors are not complete; the copy&apos;s components were not examined)</source>
        <translation> （特征向量不完备；未检查副本的各分量）</translation>
    </message>
    <message>
        <source>vertex subdivisions must be square and non-empty, got %1 and %2</source>
        <translation>顶点细分矩阵必须是非空方阵，实际为 %1 和 %2</translation>
    </message>
    <message>
        <source>the free columns must have %1 rows (n_l + n_r), got X %2 and Y %3</source>
        <translation>自由列必须有 %1 行（n_l + n_r），实际 X 为 %2、Y 为 %3</translation>
    </message>
    <message>
        <source>free columns X of T^l</source>
        <translation>T^l 的自由列 X</translation>
    </message>
    <message>
        <source>free columns Y of T^r</source>
        <translation>T^r 的自由列 Y</translation>
    </message>
    <message>
        <source>the free columns X of T^l</source>
        <translation>T^l 的自由列 X</translation>
    </message>
    <message>
        <source>the free columns Y of T^r</source>
        <translation>T^r 的自由列 Y</translation>
    </message>
    <message>
        <source>the %1 curve&apos;s subdivision operators must both be m x m, got %2 and %3</source>
        <translation>%1 曲线的细分算子必须都是 m x m，实际为 %2 和 %3</translation>
    </message>
    <message>
        <source>the %1 curve&apos;s vertex dimension must be in 1..%2, got %3</source>
        <translation>%1 曲线的顶点维数必须在 1..%2 内，实际为 %3</translation>
    </message>
    <message>
        <source>the %1 curve needs %2 control points, got %3</source>
        <translation>%1 曲线需要 %2 个控制点，实际为 %3 个</translation>
    </message>
    <message>
        <source>control points of the %1 curve</source>
        <translation>%1 曲线的控制点</translation>
    </message>
    <message>
        <source>both curves&apos; control points must have the same dimension</source>
        <translation>两条曲线的控制点必须具有相同的维数</translation>
    </message>
    <message>
        <source>X must have m_l - n_l columns and Y m_r - n_r</source>
        <translation>X 必须有 m_l - n_l 列，Y 必须有 m_r - n_r 列</translation>
    </message>
    <message>
        <source>junction parameter %1 is not a finite number</source>
        <translation>拼接参数 %1 不是有限数</translation>
    </message>
    <message>
        <source>T^i has no subdominant eigenvalue</source>
        <translation>T^i 没有次占优特征值</translation>
    </message>
    <message>
        <source>lambda_2 = %1 (%2)</source>
        <translation>lambda_2 = %1（%2）</translation>
    </message>
    <message>
        <source>: |lambda_2| &gt;= 1, T^i does not contract and the junction does not converge</source>
        <translation>：|lambda_2| &gt;= 1，T^i 不压缩，拼接不收敛</translation>
    </message>
    <message>
        <source>: both sides have half-tangents along the same eigenvector, from opposite sides: G1 at the junction point</source>
        <translation>：两侧都有沿同一特征向量、方向相反的单侧切线：在拼接点处为 G1</translation>
    </message>
    <message>
        <source>: both sides have half-tangents, but they are not opposite (a corner or cusp)</source>
        <translation>：两侧都有单侧切线，但方向并不相反（角点或尖点）</translation>
    </message>
    <message>
        <source>the cubic needs 4 and the quadratic 3 control points of one dimension, got %1 and %2</source>
        <translation>三次曲线需要 4 个、二次曲线需要 3 个维数相同的控制点，实际为 %1 个和 %2 个</translation>
    </message>
    <message>
        <source>%1 must exceed the other eigenvalues of %2 (largest modulus %3) to be subdominant, and be below 1 for %2 to contract</source>
        <translation>%1 必须大于 %2 的其他特征值（最大模为 %3）才能成为次占优特征值，并且必须小于 1 才能使 %2 压缩</translation>
    </message>
    <message>
        <source>refined junction parameter %1 is not a finite number</source>
        <translation>细化拼接参数 %1 不是有限数</translation>
    </message>
    <message>
        <source>refined junction parameter %1 = %2 is outside its admissible range (%3, %4): %5</source>
        <translation>细化拼接参数 %1 = %2 超出其容许范围 (%3, %4)：%5</translation>
    </message>
    <message>
        <source>the refined junction needs 4 cubic, 3 quadratic and 3 handle control points of one dimension, got %1, %2 and %3</source>
        <translation>细化拼接需要维数相同的 4 个三次曲线控制点、3 个二次曲线控制点和 3 个控制柄控制点，实际为 %1 个、%2 个和 %3 个</translation>
    </message>
    <message>
        <source>handles of the refined junction</source>
        <translation>细化拼接的控制柄</translation>
    </message>
    <message>
        <source>the split parameter u is not a finite number</source>
        <translation>分割参数 u 不是有限数</translation>
    </message>
    <message>
        <source>the split parameter u = %1 must lie strictly between 0 and 1 (002 §4: 0 &lt; u &lt; 1)</source>
        <translation>分割参数 u = %1 必须严格介于 0 和 1 之间（002 §4：0 &lt; u &lt; 1）</translation>
    </message>
    <message>
        <source>coincide</source>
        <comment>points</comment>
        <translation>重合</translation>
    </message>
    <message>
        <source>are collinear</source>
        <comment>points</comment>
        <translation>共线</translation>
    </message>
    <message>
        <source>are coplanar</source>
        <comment>points</comment>
        <translation>共面</translation>
    </message>
    <message>
        <source>the affine map is not invertible (its linear part is singular)</source>
        <translation>该仿射映射不可逆（其线性部分是奇异的）</translation>
    </message>
    <message>
        <source>an affine map of R^%1 is fixed by %2 point pairs</source>
        <translation>R^%1 的仿射映射由 %2 对点确定</translation>
    </message>
    <message>
        <source>source points</source>
        <translation>源点</translation>
    </message>
    <message>
        <source>target points</source>
        <translation>目标点</translation>
    </message>
    <message>
        <source>the source points %1: no unique affine map takes them to the targets</source>
        <translation>源点%1：不存在将其映射到目标点的唯一仿射映射</translation>
    </message>
    <message>
        <source>fractal interpolation needs N + 1 &gt;= 3 data points (x, y)</source>
        <translation>分形插值需要 N + 1 &gt;= 3 个数据点 (x, y)</translation>
    </message>
    <message>
        <source>interpolation data</source>
        <translation>插值数据</translation>
    </message>
    <message>
        <source>fractal interpolation through %1 points needs %2 vertical scalings d_n, got %3</source>
        <translation>经过 %1 个点的分形插值需要 %2 个竖直缩放因子 d_n，实际为 %3 个</translation>
    </message>
    <message>
        <source>interpolation abscissae must increase (x_%1 &lt;= x_%2)</source>
        <translation>插值横坐标必须递增（x_%1 &lt;= x_%2）</translation>
    </message>
    <message>
        <source>vertical scaling d_%1 = %2 must satisfy |d_n| &lt; 1</source>
        <translation>竖直缩放因子 d_%1 = %2 必须满足 |d_n| &lt; 1</translation>
    </message>
    <message>
        <source>002 §5 needs three control points in the plane (3 x 2)</source>
        <translation>002 §5 需要平面上的三个控制点（3 x 2）</translation>
    </message>
    <message>
        <source>control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>control points Q0, Q1, Q2 are collinear: the map omega of 002 §5 is not invertible</source>
        <translation>控制点 Q0、Q1、Q2 共线：002 §5 中的映射 omega 不可逆</translation>
    </message>
    <message>
        <source>a Bézier curve needs at least 2 control points (degree &gt;= 1), got %1</source>
        <translation>Bézier 曲线至少需要 2 个控制点（次数 &gt;= 1），实际为 %1 个</translation>
    </message>
    <message>
        <source>control points must have 1 to 3 coordinates</source>
        <translation>控制点必须有 1 到 3 个坐标</translation>
    </message>
    <message>
        <source>the %1 control points %2, so the affine maps of eqs. (9)-(10) are not unique</source>
        <translation>这 %1 个控制点%2，因此 eqs. (9)-(10) 的仿射映射不唯一</translation>
    </message>
    <message>
        <source>no affine map of R^%1 takes the control polygon of this degree-%2 curve to its de Casteljau pieces (mismatch %3): the pieces are not affine images of the curve in its own space</source>
        <translation>R^%1 中没有仿射映射能将此 %2 次曲线的控制多边形映射为其 de Casteljau 片段（失配 %3）：这些片段不是该曲线在其自身空间中的仿射像</translation>
    </message>
    <message>
        <source>; the maps act on barycentric coordinates R^%1 (%2)</source>
        <translation>；映射作用于重心坐标 R^%1（%2）</translation>
    </message>
    <message>
        <source>; the maps act on the lifted space R^%1 of 000 §2, drawn through its first %2 coordinates</source>
        <translation>；映射作用于 000 §2 的提升空间 R^%1，并通过其前 %2 个坐标绘制</translation>
    </message>
    <message>
        <source>map 1 has spectral radius %1, map 2 %2; %3 levels shrink every piece to 1/1000 of the curve</source>
        <translation>映射 1 的谱半径为 %1，映射 2 的为 %2；经过 %3 层后，每个片段都缩小到曲线的 1/1000</translation>
    </message>
    <message>
        <source>. u = %1 is close to %2: map %3 is nearly non-contractive and the pieces are very unequal (random iteration, or u nearer 1/2, converges faster)</source>
        <translation>。u = %1 接近 %2：映射 %3 几乎不压缩，各片段大小相差悬殊（随机迭代，或取更接近 1/2 的 u，收敛更快）</translation>
    </message>
    <message>
        <source>. Map %1 is not a Euclidean contraction (||A||_2 = %2) but is eventually contractive, as 002 §5 allows</source>
        <translation>。映射 %1 不是欧氏压缩（||A||_2 = %2），但它是最终压缩的，这是 002 §5 所允许的</translation>
    </message>
    <message>
        <source>a combined IFS needs at least one curve</source>
        <translation>组合 IFS 至少需要一条曲线</translation>
    </message>
    <message>
        <source>curve %1</source>
        <translation>曲线 %1</translation>
    </message>
    <message>
        <source>%1: the combined IFS of 002 §6 acts on the plane, control points need 2 coordinates</source>
        <translation>%1：002 §6 的组合 IFS 作用于平面，控制点需要 2 个坐标</translation>
    </message>
    <message>
        <source>%1: its maps do not act on the plane (%2), so they cannot be combined with the other curves&apos; maps</source>
        <translation>%1：其映射不作用于平面（%2），因此无法与其他曲线的映射组合</translation>
    </message>
    <message>
        <source>a union needs at least one curve</source>
        <translation>并集至少需要一条曲线</translation>
    </message>
    <message>
        <source>arc &apos;%1&apos; (%2 -&gt; %3)</source>
        <translation>弧“%1”（%2 -&gt; %3）</translation>
    </message>
    <message>
        <source>the automaton has no states</source>
        <translation>该自动机没有状态</translation>
    </message>
    <message>
        <source>state &apos;%1&apos; has no control points</source>
        <translation>状态“%1”没有控制点</translation>
    </message>
    <message>
        <source>state &apos;%1&apos;: control points must be 2D or 3D, got %2 coordinates</source>
        <translation>状态“%1”：控制点必须是 2D 或 3D 的，实际有 %2 个坐标</translation>
    </message>
    <message>
        <source>control points of state &apos;%1&apos;</source>
        <translation>状态“%1”的控制点</translation>
    </message>
    <message>
        <source>at most 255 arcs are supported (addresses are bytes), got %1</source>
        <translation>最多支持 255 条弧（地址以字节存储），实际为 %1 条</translation>
    </message>
    <message>
        <source>arc &apos;%1&apos; connects states %2 -&gt; %3, but the automaton has %4 states</source>
        <translation>弧“%1”连接状态 %2 -&gt; %3，但该自动机只有 %4 个状态</translation>
    </message>
    <message>
        <source>%1 has a %2 x %3 matrix; it must be %4 x %5 (row convention: rows = dimension of &apos;%6&apos;, columns = dimension of &apos;%7&apos;)</source>
        <translation>%1 的矩阵为 %2 x %3；它必须为 %4 x %5（行约定：行数 = “%6”的维数，列数 = “%7”的维数）</translation>
    </message>
    <message>
        <source>row %1 of %2 sums to %3, not 1: the map does not keep barycentric coordinates summing to 1</source>
        <translation>%2 的第 %1 行之和为 %3，而不是 1：该映射不能保持重心坐标之和为 1</translation>
    </message>
    <message>
        <source>the weight of %1 must be a finite number &gt; 0, got %2</source>
        <translation>%1 的权重必须是 &gt; 0 的有限数，实际为 %2</translation>
    </message>
    <message>
        <source>state &apos;%1&apos; has no outgoing arc: its attractor would be empty</source>
        <translation>状态“%1”没有出弧：其吸引子将为空</translation>
    </message>
    <message>
        <source>the barycentric part needs a non-empty square matrix</source>
        <translation>重心坐标部分需要非空方阵</translation>
    </message>
    <message>
        <source>cycle %1 has spectral radius %2 &gt;= 1 on the barycentric directions: repeating it does not contract, so the automaton has no attractor</source>
        <translation>环路 %1 在重心坐标方向上的谱半径为 %2 &gt;= 1：重复该环路不会压缩，因此该自动机没有吸引子</translation>
    </message>
    <message>
        <source>a fixed point needs a non-empty square matrix</source>
        <translation>求不动点需要非空方阵</translation>
    </message>
    <message>
        <source>the fixed point is not unique: 1 is a repeated eigenvalue</source>
        <translation>不动点不唯一：1 是重特征值</translation>
    </message>
    <message>
        <source>state %1 does not exist: the automaton has %2 states</source>
        <translation>状态 %1 不存在：该自动机有 %2 个状态</translation>
    </message>
    <message>
        <source>one start set per state is needed: the automaton has %1 states, got %2 start sets</source>
        <translation>每个状态需要一个初始集：该自动机有 %1 个状态，实际给出 %2 个初始集</translation>
    </message>
    <message>
        <source>start set of state &apos;%1&apos;</source>
        <translation>状态“%1”的初始集</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 为空</translation>
    </message>
    <message>
        <source>%1 has %2 coordinates, the state&apos;s space has %3</source>
        <translation>%1 有 %2 个坐标，而该状态的空间有 %3 个</translation>
    </message>
    <message>
        <source>at most 4e9 random-iteration samples, got %1</source>
        <translation>随机迭代的样本数最多为 4e9，实际为 %1</translation>
    </message>
    <message>
        <source>the affine map&apos;s translation does not match its linear part</source>
        <translation>仿射映射的平移部分与其线性部分不匹配</translation>
    </message>
    <message>
        <source>a barycentric frame in %1D needs %2 points, got a %3 x %4 matrix</source>
        <translation>%1D 中的重心坐标框架需要 %2 个点，实际为 %3 x %4 矩阵</translation>
    </message>
    <message>
        <source>domain frame</source>
        <translation>定义域框架</translation>
    </message>
    <message>
        <source>image frame</source>
        <translation>像框架</translation>
    </message>
    <message>
        <source>affine map</source>
        <translation>仿射映射</translation>
    </message>
    <message>
        <source>the image frame&apos;s points are affinely dependent (collinear in 2D)</source>
        <translation>像框架的点仿射相关（在 2D 中即共线）</translation>
    </message>
    <message>
        <source>map %1 does not act on the same space as map 1</source>
        <translation>映射 %1 与映射 1 不作用于同一空间</translation>
    </message>
    <message>
        <source>map %1 (linear part)</source>
        <translation>映射 %1（线性部分）</translation>
    </message>
    <message>
        <source>map %1 (translation)</source>
        <translation>映射 %1（平移部分）</translation>
    </message>
    <message>
        <source>view %1 does not fit the IFS space</source>
        <translation>视图 %1 与 IFS 空间不匹配</translation>
    </message>
    <message>
        <source>the IFS has %1 maps but %2 probabilities</source>
        <translation>该 IFS 有 %1 个映射，却有 %2 个概率</translation>
    </message>
    <message>
        <source>probability of map %1 must be a finite number &gt;= 0</source>
        <translation>映射 %1 的概率必须是 &gt;= 0 的有限数</translation>
    </message>
    <message>
        <source>the map probabilities sum to 0</source>
        <translation>各映射的概率之和为 0</translation>
    </message>
    <message>
        <source>the lifting needs %1 distinct free rows of the control points</source>
        <translation>提升需要控制点中 %1 个互不相同的自由行</translation>
    </message>
    <message>
        <source> and </source>
        <translation> 和 </translation>
    </message>
    <message>
        <source>the lifted matrix P is nearly singular (reciprocal condition number %1): M_i = P^-1 S_i P lose about %2 of 16 significant digits; control points %3 are almost collinear</source>
        <translation>提升矩阵 P 接近奇异（条件数倒数为 %1）：M_i = P^-1 S_i P 约损失 16 位有效数字中的 %2 位；控制点 %3 几乎共线</translation>
    </message>
    <message>
        <source>the lifted matrix P is nearly singular (reciprocal condition number %1): M_i = P^-1 S_i P lose about %2 of 16 significant digits; control points %3 are almost coplanar</source>
        <translation>提升矩阵 P 接近奇异（条件数倒数为 %1）：M_i = P^-1 S_i P 约损失 16 位有效数字中的 %2 位；控制点 %3 几乎共面</translation>
    </message>
    <message>
        <source>control points %1 are collinear, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>控制点 %1 共线，因此 000 §2 的提升矩阵 P 是奇异的，M_i = P^-1 S_i P 没有定义；吸引子改用重心坐标形式计算</translation>
    </message>
    <message>
        <source>control points %1 are coplanar, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>控制点 %1 共面，因此 000 §2 的提升矩阵 P 是奇异的，M_i = P^-1 S_i P 没有定义；吸引子改用重心坐标形式计算</translation>
    </message>
    <message>
        <source>control points %1 are affinely dependent, so the lifted matrix P of 000 §2 is singular and M_i = P^-1 S_i P is not defined; the attractor is computed in barycentric form</source>
        <translation>控制点 %1 仿射相关，因此 000 §2 的提升矩阵 P 是奇异的，M_i = P^-1 S_i P 没有定义；吸引子改用重心坐标形式计算</translation>
    </message>
    <message>
        <source>matrix S_%1 does not match %2 control points</source>
        <translation>矩阵 S_%1 与 %2 个控制点不匹配</translation>
    </message>
    <message>
        <source>matrix S_%1</source>
        <translation>矩阵 S_%1</translation>
    </message>
    <message>
        <source>start points must have %1 (plane) or %2 (barycentric) coordinates</source>
        <translation>初始点必须有 %1 个（平面）或 %2 个（重心坐标）坐标</translation>
    </message>
    <message>
        <source>start points must have %1 (plane) or %2 (lifted) coordinates</source>
        <translation>初始点必须有 %1 个（平面）或 %2 个（提升）坐标</translation>
    </message>
    <message>
        <source>a union needs at least one component</source>
        <translation>并集至少需要一个组成部分</translation>
    </message>
    <message>
        <source>component %1 has %2 maps, component 1 has %3: a block union needs equally many</source>
        <translation>组成部分 %1 有 %2 个映射，而组成部分 1 有 %3 个：块并集要求各部分的映射数相同</translation>
    </message>
    <message>
        <source>probabilities must be finite and non-negative</source>
        <translation>概率必须是非负的有限数</translation>
    </message>
    <message>
        <source>the probabilities sum to zero</source>
        <translation>概率之和为零</translation>
    </message>
    <message>
        <source>the lattice lists %1 coordinates for %2 control points</source>
        <translation>格点列出了 %1 个坐标，但有 %2 个控制点</translation>
    </message>
    <message>
        <source>a map is listed twice among the maps used</source>
        <translation>所用映射中有一个映射被列出了两次</translation>
    </message>
    <message>
        <source>map index %1 is out of range: the %2 layout has maps 0 to %3</source>
        <translation>映射索引 %1 超出范围：%2 布局的映射编号为 0 到 %3</translation>
    </message>
    <message>
        <source>at most %1 maps are supported, got %2</source>
        <translation>最多支持 %1 个映射，实际为 %2 个</translation>
    </message>
    <message>
        <source>the barycentric part needs a non-empty matrix</source>
        <translation>重心部分需要非空矩阵</translation>
    </message>
</context>
<context>
    <name>awb::mesh</name>
    <message>
        <source>the mesh has no vertices</source>
        <translation>网格没有顶点</translation>
    </message>
    <message>
        <source>the mesh has no faces</source>
        <translation>网格没有面</translation>
    </message>
    <message>
        <source>face %1 has %2 vertices; a face needs at least 3</source>
        <translation>面 %1 有 %2 个顶点；一个面至少需要 3 个</translation>
    </message>
    <message>
        <source>face %1 refers to vertex %2, but the mesh has %3 vertices (0 to %4)</source>
        <translation>面 %1 引用了顶点 %2，但网格只有 %3 个顶点（0 到 %4）</translation>
    </message>
    <message>
        <source>face %1 lists vertex %2 twice</source>
        <translation>面 %1 两次列出顶点 %2</translation>
    </message>
    <message>
        <source>edge (%1, %2) is non-manifold: faces %3 meet there</source>
        <translation>边 (%1, %2) 非流形：面 %3 在此相交</translation>
    </message>
    <message>
        <source>faces %1 and %2 are oriented inconsistently: both run from vertex %3 to vertex %4 (turn one of them over)</source>
        <translation>面 %1 和 %2 的朝向不一致：两者都从顶点 %3 走向顶点 %4（请翻转其中一个）</translation>
    </message>
    <message>
        <source>vertex %1 is non-manifold: its %2 faces do not form one fan around it</source>
        <translation>顶点 %1 非流形：其 %2 个面未在其周围构成一个扇形</translation>
    </message>
    <message>
        <source>mesh vertices need 3 coordinates, got %1</source>
        <translation>网格顶点需要 3 个坐标，得到 %1 个</translation>
    </message>
    <message>
        <source>vertex %1 has a coordinate that is not a finite number</source>
        <translation>顶点 %1 的某个坐标不是有限数</translation>
    </message>
    <message>
        <source>face %1 has %2 vertices; Loop subdivision takes triangles only</source>
        <translation>面 %1 有 %2 个顶点；Loop 细分只接受三角形</translation>
    </message>
    <message>
        <source>a vertex&apos;s valence must be 3 to 64, got %1</source>
        <translation>顶点的价必须为 3 到 64，得到 %1</translation>
    </message>
    <message>
        <source>a characteristic map needs ring x 2 points</source>
        <translation>特征映射需要环上的点 × 2</translation>
    </message>
    <message>
        <source>a grid needs 1 to 1000 quads a side, got %1 x %2</source>
        <translation>方格网每边需要 1 到 1000 个四边形，实际为 %1 x %2</translation>
    </message>
    <message>
        <source>there is no example mesh &apos;%1&apos;</source>
        <translation>没有名为“%1”的示例网格</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1，第 %2 行</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1：“%2”不是数字</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a finite number</source>
        <translation>%1：“%2”不是有限数</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a whole number</source>
        <translation>%1：“%2”不是整数</translation>
    </message>
    <message>
        <source>%1: a vertex needs 3 coordinates, this one has %2</source>
        <translation>%1：顶点需要 3 个坐标，此顶点有 %2 个</translation>
    </message>
    <message>
        <source>%1: a face needs at least 3 vertices, this one has %2</source>
        <translation>%1：面至少需要 3 个顶点，此面有 %2 个</translation>
    </message>
    <message>
        <source>%1: vertex index %2 is out of range (the file has %3 vertices)</source>
        <translation>%1：顶点索引 %2 超出范围（文件有 %3 个顶点）</translation>
    </message>
    <message>
        <source>%1 holds no vertices</source>
        <translation>%1 不含顶点</translation>
    </message>
    <message>
        <source>%1 holds no faces: not a polygon mesh</source>
        <translation>%1 不含面：不是多边形网格</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a face corner (v, v/vt, v//vn or v/vt/vn, nonzero whole numbers)</source>
        <translation>%1：“%2”不是面的角点（v、v/vt、v//vn 或 v/vt/vn，非零整数）</translation>
    </message>
    <message>
        <source>%1: relative vertex index %2 is out of range (%3 vertices precede it)</source>
        <translation>%1：相对顶点索引 %2 超出范围（其前面只有 %3 个顶点）</translation>
    </message>
    <message>
        <source>%1 is not a valid OBJ file (tinyobjloader: %2)</source>
        <translation>%1 不是有效的 OBJ 文件（tinyobjloader：%2）</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 为空</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a header this reader takes: ASCII OFF of 3D points ([ST][C][N]OFF)</source>
        <translation>%1：“%2”不是此读取器接受的文件头：仅支持三维点的 ASCII OFF（[ST][C][N]OFF）</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not the counts line (vertices, faces and edges) of an OFF file</source>
        <translation>%1：“%2”不是 OFF 文件的计数行（顶点数、面数和边数）</translation>
    </message>
    <message>
        <source>%1: %2 vertices and %3 faces need more lines than the %4 left in the file</source>
        <translation>%1：%2 个顶点和 %3 个面所需的行数多于文件中剩余的 %4 行</translation>
    </message>
    <message>
        <source>%1 ends after %2 of its %3 vertices</source>
        <translation>%1 在其 %3 个顶点中读到第 %2 个后就结束了</translation>
    </message>
    <message>
        <source>%1 ends after %2 of its %3 faces</source>
        <translation>%1 在其 %3 个面中读到第 %2 个后就结束了</translation>
    </message>
    <message>
        <source>%1: the face announces %2 vertices but lists %3</source>
        <translation>%1：该面声明有 %2 个顶点，但列出了 %3 个</translation>
    </message>
    <message>
        <source>%1: data after the last face (the counts announce %2 vertices and %3 faces)</source>
        <translation>%1：最后一个面之后还有数据（计数声明了 %2 个顶点和 %3 个面）</translation>
    </message>
    <message>
        <source>%1: a property outside any element</source>
        <translation>%1：属性不在任何元素之内</translation>
    </message>
    <message>
        <source>%1: unknown PLY property type &apos;%2&apos;</source>
        <translation>%1：未知的 PLY 属性类型“%2”</translation>
    </message>
    <message>
        <source>%1: a list&apos;s length needs a whole-number type</source>
        <translation>%1：列表长度需要整数类型</translation>
    </message>
    <message>
        <source>%1: property %2 appears twice in element %3</source>
        <translation>%1：属性 %2 在元素 %3 中出现了两次</translation>
    </message>
    <message>
        <source>%1 is not a PLY file (its first line is not &apos;ply&apos;)</source>
        <translation>%1 不是 PLY 文件（其第一行不是“ply”）</translation>
    </message>
    <message>
        <source>%1: the PLY header has no end_header line</source>
        <translation>%1：PLY 文件头没有 end_header 行</translation>
    </message>
    <message>
        <source>%1: unsupported PLY format &apos;%2&apos; (ascii, binary_little_endian or binary_big_endian 1.0)</source>
        <translation>%1：不支持的 PLY 格式“%2”（应为 ascii、binary_little_endian 或 binary_big_endian 1.0）</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a valid count</source>
        <translation>%1：“%2”不是有效的计数</translation>
    </message>
    <message>
        <source>%1: element %2 appears twice</source>
        <translation>%1：元素 %2 出现了两次</translation>
    </message>
    <message>
        <source>%1: unknown PLY header line &apos;%2&apos;</source>
        <translation type="vanished">%1：未知的 PLY 文件头行“%2”</translation>
    </message>
    <message>
        <source>%1: the PLY header has no format line</source>
        <translation>%1：PLY 文件头没有 format 行</translation>
    </message>
    <message>
        <source>%1: the vertex element needs the scalar properties x, y and z</source>
        <translation>%1：vertex 元素需要标量属性 x、y 和 z</translation>
    </message>
    <message>
        <source>%1: the face element needs one list property vertex_indices (or vertex_index) of whole numbers</source>
        <translation>%1：face 元素需要一个整数列表属性 vertex_indices（或 vertex_index）</translation>
    </message>
    <message>
        <source>%1, line %2 (%3 %4)</source>
        <translation>%1，第 %2 行（%3 %4）</translation>
    </message>
    <message>
        <source>%1, %2 %3 (byte %4)</source>
        <translation>%1，%2 %3（字节 %4）</translation>
    </message>
    <message>
        <source>%1: element %2 claims %3 items, more than the rest of the file can hold</source>
        <translation>%1：元素 %2 声明了 %3 项，超出文件剩余部分所能容纳的数量</translation>
    </message>
    <message>
        <source>%1: the data ends early (truncated)</source>
        <translation>%1：数据提前结束（文件被截断）</translation>
    </message>
    <message>
        <source>%1: data after the last element (the header&apos;s counts do not match the data)</source>
        <translation>%1：最后一个元素之后还有数据（文件头中的计数与数据不符）</translation>
    </message>
    <message>
        <source>%1, byte %2</source>
        <translation>%1，字节 %2</translation>
    </message>
    <message>
        <source>%1: list length %2 is negative</source>
        <translation>%1：列表长度 %2 为负数</translation>
    </message>
    <message>
        <source>%1 has no file extension (expected .obj, .off or .ply)</source>
        <translation>%1 没有文件扩展名（应为 .obj、.off 或 .ply）</translation>
    </message>
    <message>
        <source>unknown mesh file extension &apos;%1&apos; of %2 (expected .obj, .off or .ply)</source>
        <translation>%2 的网格文件扩展名“%1”未知（应为 .obj、.off 或 .ply）</translation>
    </message>
    <message>
        <source>cannot open %1</source>
        <translation>无法打开 %1</translation>
    </message>
    <message>
        <source>cannot read %1</source>
        <translation>无法读取 %1</translation>
    </message>
    <message>
        <source>%1: a NUL byte: not a text file</source>
        <translation>%1：含有 NUL 字节：不是文本文件</translation>
    </message>
    <message>
        <source>the mesh has %1 vertices, but %2 positions were given</source>
        <translation>网格有 %1 个顶点，但给出了 %2 个位置</translation>
    </message>
    <message>
        <source>mesh vertices</source>
        <translation>网格顶点</translation>
    </message>
    <message>
        <source>depth %1 makes about %2 points; at most 2^31 are drawn</source>
        <translation>深度 %1 将产生约 %2 个点；最多绘制 2^31 个</translation>
    </message>
    <message>
        <source>the mesh has more than %1 kinds of neighbourhood</source>
        <translation>网格的邻域类型多于 %1 种</translation>
    </message>
    <message>
        <source>the irregular vertices do not separate</source>
        <translation>非正则顶点无法分离</translation>
    </message>
    <message>
        <source>vertex %1 has %2 edges; valences above %3 are not supported</source>
        <translation>顶点 %1 有 %2 条边；不支持大于 %3 的价</translation>
    </message>
    <message>
        <source>face %1 has %2 sides; faces of more than %3 sides are not supported</source>
        <translation>面 %1 有 %2 条边；不支持多于 %3 条边的面</translation>
    </message>
    <message>
        <source>%1, line %2: the OpenSubdiv tag &apos;t %3&apos; is not applied: this version subdivides without creases, corners, holes or boundary rules, so the surface differs from OpenSubdiv&apos;s where it acts</source>
        <translation type="vanished">%1，第 %2 行：OpenSubdiv 标签 &apos;t %3&apos; 未被应用：此版本细分时不考虑折痕、角点、孔洞和边界规则，因此在其作用处曲面与 OpenSubdiv 的不同</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 OpenSubdiv tags &apos;t %5&apos; are not applied: this version subdivides without creases, corners, holes or boundary rules, so the surface differs from OpenSubdiv&apos;s where they act</source>
        <translation type="vanished">%1，第 %2 至 %3 行：%4 个 OpenSubdiv 标签 &apos;t %5&apos; 未被应用：此版本细分时不考虑折痕、角点、孔洞和边界规则，因此在其作用处曲面与 OpenSubdiv 的不同</translation>
    </message>
    <message>
        <source>%1: UTF-16 text of an odd number of bytes</source>
        <translation>%1：UTF-16 文本的字节数为奇数</translation>
    </message>
    <message>
        <source>%1: invalid UTF-16 text (a lone surrogate)</source>
        <translation>%1：无效的 UTF-16 文本（孤立的代理项）</translation>
    </message>
    <message>
        <source>%1: malformed PLY header line &apos;%2&apos;</source>
        <translation>%1：格式错误的 PLY 头行 &apos;%2&apos;</translation>
    </message>
    <message>
        <source>%1: header line &apos;%2&apos; is not PLY 1.0&apos;s: skipped</source>
        <translation>%1：头行 &apos;%2&apos; 不属于 PLY 1.0：已跳过</translation>
    </message>
    <message>
        <source>%1 problems, the first %2: %3</source>
        <translation>%1 个问题，前 %2 个：%3</translation>
    </message>
    <message>
        <source>%1 problems: %2</source>
        <translation>%1 个问题：%2</translation>
    </message>
    <message>
        <source>the ring analysis takes interior valences 3 to 64; this vertex has %1</source>
        <translation>环分析只接受 3 到 64 的内部价数；此顶点的价数为 %1</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 more OpenSubdiv tag lines of other names are not applied either</source>
        <translation>%1，第 %2 至 %3 行：另有 %4 行其他名称的 OpenSubdiv 标签同样未被应用</translation>
    </message>
    <message>
        <source>%1: %2 header lines that are not PLY 1.0&apos;s, the first &apos;%3&apos;, are skipped</source>
        <translation>%1：已跳过 %2 行不属于 PLY 1.0 的头行，第一行为 &apos;%3&apos;</translation>
    </message>
    <message>
        <source>the crease on vertices %1 and %2 has sharpness %3; a sharpness is a number of 0 or more</source>
        <translation>顶点 %1 和 %2 上的折痕锐度为 %3；锐度应为大于或等于 0 的数</translation>
    </message>
    <message>
        <source>a crease names vertices %1 and %2, but no edge joins them</source>
        <translation>折痕指定了顶点 %1 和 %2，但没有边连接这两个顶点</translation>
    </message>
    <message>
        <source>a corner names vertex %1, but the mesh has %2 vertices (0 to %3)</source>
        <translation>角点指定了顶点 %1，但网格共有 %2 个顶点（0 到 %3）</translation>
    </message>
    <message>
        <source>the corner at vertex %1 has sharpness %2; a sharpness is a number of 0 or more</source>
        <translation>顶点 %1 处的角点锐度为 %2；锐度应为大于或等于 0 的数</translation>
    </message>
    <message>
        <source>a hole names face %1, but the mesh has %2 faces (0 to %3)</source>
        <translation>孔洞指定了面 %1，但网格共有 %2 个面（0 到 %3）</translation>
    </message>
    <message>
        <source>%1, line %2: the OpenSubdiv tag &apos;t %3&apos; is not applied (this version applies crease, corner, hole, interpolateboundary, creasemethod and smoothtriangles), so the surface differs from OpenSubdiv&apos;s where it acts</source>
        <translation>%1，第 %2 行：未应用 OpenSubdiv 标签 &apos;t %3&apos;（此版本应用 crease、corner、hole、interpolateboundary、creasemethod 和 smoothtriangles），因此在该标签起作用之处，曲面与 OpenSubdiv 的结果不同</translation>
    </message>
    <message>
        <source>%1, lines %2 to %3: %4 OpenSubdiv tags &apos;t %5&apos; are not applied (this version applies crease, corner, hole, interpolateboundary, creasemethod and smoothtriangles), so the surface differs from OpenSubdiv&apos;s where they act</source>
        <translation>%1，第 %2 至 %3 行：未应用 %4 个 OpenSubdiv 标签 &apos;t %5&apos;（此版本应用 crease、corner、hole、interpolateboundary、creasemethod 和 smoothtriangles），因此在这些标签起作用之处，曲面与 OpenSubdiv 的结果不同</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; needs its counts as ints/floats/strings (like 2/1/0), got &apos;%3&apos;</source>
        <translation>%1：标签 &apos;t %2&apos; 的计数应写成 ints/floats/strings 的形式（如 2/1/0），实际为“%3”</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; announces %3 values but has %4</source>
        <translation>%1：标签 &apos;t %2&apos; 声明了 %3 个值，但实际有 %4 个</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; needs %3</source>
        <translation>%1：标签 &apos;t %2&apos; 需要%3</translation>
    </message>
    <message>
        <source>%1: the tag &apos;t %2&apos; names vertex %3, but the file has %4 vertices (tags count from 0: 0 to %5)</source>
        <translation>%1：标签 &apos;t %2&apos; 指定了顶点 %3，但文件共有 %4 个顶点（标签从 0 开始计数：0 到 %5）</translation>
    </message>
    <message>
        <source>%1: the hole names face %2, but the file has %3 faces (0 to %4)</source>
        <translation>%1：孔洞指定了面 %2，但文件共有 %3 个面（0 到 %4）</translation>
    </message>
    <message>
        <source>Chaikin&apos;s creases last %1 more levels here; the mesh would have more than %2 faces (use the uniform crease method)</source>
        <translation>此处 Chaikin 折痕还将持续 %1 层；网格将超过 %2 个面（请使用均匀折痕方法）</translation>
    </message>
    <message>
        <source>the semi-sharp features last %1 levels; the mesh would have more than %2 faces before its limit positions can be taken</source>
        <translation>半锐特征持续 %1 层；在能够求得极限位置之前，网格将超过 %2 个面</translation>
    </message>
    <message>
        <source>pairs of vertices and one sharpness, or one per pair</source>
        <translation>若干顶点对及一个锐度，或每对顶点各一个锐度</translation>
    </message>
    <message>
        <source>vertices and one sharpness, or one per vertex</source>
        <translation>若干顶点及一个锐度，或每个顶点各一个锐度</translation>
    </message>
    <message>
        <source>the faces it makes holes</source>
        <translation>要设为孔洞的面</translation>
    </message>
    <message>
        <source>one whole number: 0 none, 1 edge and corner, 2 edge only</source>
        <translation>一个整数：0 表示无，1 表示边和角点，2 表示仅边</translation>
    </message>
    <message>
        <source>one word: normal or chaikin</source>
        <translation>一个单词：normal 或 chaikin</translation>
    </message>
    <message>
        <source>one word: catmark or smooth</source>
        <translation>一个单词：catmark 或 smooth</translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation> 以及另外 %1 个</translation>
    </message>
    <message>
        <source>%1 faces named a vertex twice in a row and now name it once (faces %2)</source>
        <translation>%1 个面连续两次列出同一顶点，现在只列出一次（面 %2）</translation>
    </message>
    <message>
        <source>%1 faces were left with fewer than three vertices and were removed (faces %2; the later faces move up)</source>
        <translation>%1 个面剩余不到三个顶点，已被删除（面 %2；后面的面依次前移）</translation>
    </message>
    <message>
        <source>%1 boundary vertices at the position of another were welded into it (vertices %2; they stay, used by no face)</source>
        <translation>%1 个边界顶点与另一顶点位置相同，已焊接到该顶点（顶点 %2；它们保留，但不被任何面使用）</translation>
    </message>
    <message>
        <source>%1 faces were turned over to the orientation of the surface they belong to (faces %2)</source>
        <translation>%1 个面已翻转为其所属曲面的定向（面 %2）</translation>
    </message>
    <message>
        <source>the surface of face %1 cannot be oriented (it is a Möbius band or contains one): left as it is</source>
        <translation>面 %1 所在的曲面不可定向（它是或包含莫比乌斯带）：保持原样</translation>
    </message>
    <message>
        <source>%1 vertices whose faces formed several fans were split, one vertex per fan (vertices %2; the %3 new vertices are numbered from %4)</source>
        <translation>%1 个顶点的面构成多个扇形，已拆分为每个扇形一个顶点（顶点 %2；%3 个新顶点从 %4 开始编号）</translation>
    </message>
    <message>
        <source>(%1, %2)</source>
        <translation>（%1, %2）</translation>
    </message>
    <message>
        <source>%1 edges join three or more faces (%2): no choice of sheets is canonical, so they are not repaired</source>
        <translation type="vanished">%1 条边连接三个或更多面（%2）：没有规范的分片选择，因此不予修复</translation>
    </message>
    <message>
        <source>%1 edges join three or more faces (%2): no choice of sheets is canonical, so they are not repaired; they are drawn as OpenSubdiv draws them, as infinitely sharp creases</source>
        <translation>%1 条边连接三个或更多面（%2）：没有规范的分层选择，因此不修复；它们按 OpenSubdiv 的方式绘制，作为无限尖锐的折痕</translation>
    </message>
    <message>
        <source>%1(%2, %3)</source>
        <translation>%1(%2, %3)</translation>
    </message>
    <message>
        <source>the vertices as corners</source>
        <translation>顶点作为角点</translation>
    </message>
    <message>
        <source>%1 of the vertices as corners, the others on the creases</source>
        <translation>其中 %1 个顶点作为角点，其余位于折痕上</translation>
    </message>
    <message>
        <source>non-manifold: %1 vertices (%2), drawn as OpenSubdiv draws them: %3</source>
        <translation>非流形：%1 个顶点（%2），按 OpenSubdiv 的方式绘制：%3</translation>
    </message>
    <message>
        <source>non-manifold: %1 edges (%2) and %3 vertices (%4), drawn as OpenSubdiv draws them: the edges as infinitely sharp creases, %5</source>
        <translation>非流形：%1 条边（%2）和 %3 个顶点（%4），按 OpenSubdiv 的方式绘制：边作为无限尖锐的折痕，%5</translation>
    </message>
    <message>
        <source>its largest eigenvalues below 1 are not real and positive</source>
        <translation>其小于 1 的最大特征值不是正实数</translation>
    </message>
    <message>
        <source>%1 is a defective eigenvalue (a Jordan block) among the two largest: Reif&apos;s criterion takes them diagonalizable (not decided)</source>
        <translation type="vanished">%1 是两个最大特征值中的亏损特征值（若尔当块）：Reif 判据假定其可对角化（未判定）</translation>
    </message>
    <message>
        <source>lambda2 = lambda3 = %1: the tangent plane is not determined by the two largest</source>
        <translation>lambda2 = lambda3 = %1：切平面不由两个最大特征值确定</translation>
    </message>
    <message>
        <source>its characteristic map is not regular</source>
        <translation>其特征映射不正则</translation>
    </message>
    <message>
        <source>its characteristic map is not injective</source>
        <translation>其特征映射不是单射</translation>
    </message>
    <message>
        <source>%1: %2 crease tags name an edge tagged before (the first: %3 %4): each edge keeps its last sharpness, as OpenSubdiv applies them</source>
        <translation>%1：%2 个折痕标签指向之前已标记的边（第一个：%3 %4）：每条边保留最后的锐度，与 OpenSubdiv 的应用方式相同</translation>
    </message>
    <message>
        <source>%1: %2 corner tags name a vertex tagged before (the first: %3): each vertex keeps its last sharpness, as OpenSubdiv applies them</source>
        <translation>%1：%2 个角点标签指向之前已标记的顶点（第一个：%3）：每个顶点保留最后的锐度，与 OpenSubdiv 的应用方式相同</translation>
    </message>
    <message>
        <source>%1: %2 hole tags name a face made a hole before</source>
        <translation>%1：%2 个孔标签指向之前已设为孔的面</translation>
    </message>
    <message>
        <source>lambda1 = lambda2 = %1 is a Jordan block: the rings shear, and Reif&apos;s criterion holds for the map of its eigenvector and generalized eigenvector</source>
        <translation>lambda1 = lambda2 = %1 是一个若尔当块：环发生剪切，Reif 判据对其特征向量与广义特征向量构成的映射成立</translation>
    </message>
    <message>
        <source>lambda1 = lambda2 = %1 has two eigenvectors and a Jordan chain: the normal and the rings follow the map of the two eigenvectors</source>
        <translation>lambda1 = lambda2 = %1 有两个特征向量和一条若尔当链：法向与环由两个特征向量构成的映射决定</translation>
    </message>
    <message>
        <source>lambda2 = %1 is a Jordan block: its chain&apos;s top term k lambda2^k dominates, and Reif&apos;s criterion holds for the map of the eigenvectors of lambda1 and of the chain&apos;s top</source>
        <translation>lambda2 = %1 是一个若尔当块：其链顶项 k lambda2^k 占主导，Reif 判据对 lambda1 的特征向量与链顶特征向量构成的映射成立</translation>
    </message>
    <message>
        <source>%1 is a defective eigenvalue with a Jordan chain longer than two, or more than one chain: Reif&apos;s criterion is not decided there</source>
        <translation>%1 是亏损特征值，其若尔当链长于二或不止一条：此处 Reif 判据无法判定</translation>
    </message>
    <message>
        <source>the eigenvectors of lambda1 and lambda2 vanish on the crease of edge %1, whose own tangent (a smaller eigenvalue) leaves their tangent plane: not C1 for generic data</source>
        <translation>lambda1 与 lambda2 的特征向量在折痕边 %1 上为零，而该折痕自身的切线（较小的特征值）离开它们的切平面：对一般数据不是 C1</translation>
    </message>
</context>
<context>
    <name>awb::render</name>
    <message>
        <source>raster size must be between 1x1 and 32768x32768, got %1x%2</source>
        <translation>栅格尺寸必须介于 1x1 和 32768x32768 之间，实际为 %1x%2</translation>
    </message>
    <message>
        <source>supersampling must be 1 to 4 cells per pixel side, got %1</source>
        <translation>超采样必须为每个像素每边 1 到 4 个单元，实际为 %1</translation>
    </message>
    <message>
        <source>the supersampled raster would hold more than 1.2e9 cells</source>
        <translation>超采样后的栅格将含有超过 1.2e9 个单元</translation>
    </message>
    <message>
        <source>raster world rectangle is empty or not finite</source>
        <translation>栅格的世界坐标矩形为空或不是有限的</translation>
    </message>
    <message>
        <source>cannot merge density images of different sizes or modes</source>
        <translation>无法合并尺寸或模式不同的密度图像</translation>
    </message>
    <message>
        <source>density image does not match its frame</source>
        <translation>密度图像与其取景框不匹配</translation>
    </message>
    <message>
        <source>a view does not fit the IFS space</source>
        <translation>某个视图与 IFS 空间不匹配</translation>
    </message>
    <message>
        <source>there is no IFS to draw</source>
        <translation>没有要绘制的 IFS</translation>
    </message>
    <message>
        <source>the IFS has no view to draw it with</source>
        <translation>该 IFS 没有可用于绘制的视图</translation>
    </message>
    <message>
        <source>the colour table does not cover the address labels</source>
        <translation>颜色表未覆盖所有地址标签</translation>
    </message>
</context>
<context>
    <name>awb::schemes</name>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 不是有限数</translation>
    </message>
    <message>
        <source>%1 = %2 &lt; 1</source>
        <translation>%1 = %2 &lt; 1</translation>
    </message>
    <message>
        <source>%1 = %2: on the circle %1 = 1, so %3 is an isometry, not a contraction</source>
        <translation>%1 = %2：位于圆 %1 = 1 上，因此 %3 是等距映射，而不是压缩映射</translation>
    </message>
    <message>
        <source>%1 = %2 &gt; 1, so %3 expands</source>
        <translation>%1 = %2 &gt; 1，因此 %3 是扩张的</translation>
    </message>
    <message>
        <source>y must be a finite nonzero number (t = 1/2 + i y)</source>
        <translation>y 必须是有限的非零数（t = 1/2 + i y）</translation>
    </message>
    <message>
        <source>t = 1/2 + i y with y = %1: %2</source>
        <translation>t = 1/2 + i y，y = %1：%2</translation>
    </message>
    <message>
        <source>depth must be between 1 and 24, got %1</source>
        <translation>深度必须介于 1 和 24 之间，实际为 %1</translation>
    </message>
    <message>
        <source>the subdivision parameter t</source>
        <translation>细分参数 t</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies inside both discs: the IFS is hyperbolic (contraction factor %4) and its attractor is a connected curve (Theorem 3.7.2)</source>
        <translation>t = %1：%2，%3。t 位于两个圆盘内部：该 IFS 是双曲的（压缩因子 %4），其吸引子是一条连通曲线（Theorem 3.7.2）</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies outside both discs |t| &lt; 1 and |1 - t| &lt; 1: the IFS is not hyperbolic and has no attractor</source>
        <translation>t = %1：%2，%3。t 位于两个圆盘 |t| &lt; 1 与 |1 - t| &lt; 1 之外：该 IFS 不是双曲的，没有吸引子</translation>
    </message>
    <message>
        <source>t = %1: %2, %3. t lies outside the disc %4: the IFS is not hyperbolic and has no attractor</source>
        <translation>t = %1：%2，%3。t 位于圆盘 %4 之外：该 IFS 不是双曲的，没有吸引子</translation>
    </message>
    <message>
        <source>a Bézier curve needs at least 2 control points (degree &gt;= 1), got %1</source>
        <translation>Bézier 曲线至少需要 2 个控制点（次数 &gt;= 1），实际为 %1 个</translation>
    </message>
    <message>
        <source>control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>all control points coincide: the curve is a single point and the lifted matrix of 000 §2 is singular</source>
        <translation>所有控制点重合：曲线退化为一个点，000 §2 中的提升矩阵是奇异的</translation>
    </message>
    <message>
        <source>depth must be between 0 and 24, got %1</source>
        <translation>深度必须介于 0 和 24 之间，实际为 %1</translation>
    </message>
    <message>
        <source>the Takagi function needs a finite x</source>
        <translation>Takagi 函数需要有限的 x</translation>
    </message>
    <message>
        <source>the number of Takagi terms must be &gt;= 0</source>
        <translation>Takagi 项数必须 &gt;= 0</translation>
    </message>
    <message>
        <source>binary codes longer than 60 digits are not supported</source>
        <translation>不支持长于 60 位的二进制码</translation>
    </message>
    <message>
        <source>a binary code has digits 0 and 1 only (digit %1 is %2)</source>
        <translation>二进制码只能包含数字 0 和 1（第 %1 位为 %2）</translation>
    </message>
    <message>
        <source>Takagi image: needs at least 2 control points, got %1</source>
        <translation>Takagi 像：至少需要 2 个控制点，实际为 %1 个</translation>
    </message>
    <message>
        <source>Takagi image: control points and y must be finite</source>
        <translation>Takagi 像：控制点和 y 必须是有限数</translation>
    </message>
    <message>
        <source>Takagi image: depth %1 is outside 1..20</source>
        <translation>Takagi 像：深度 %1 不在 1..20 范围内</translation>
    </message>
    <message>
        <source>control points must have 2 or 3 coordinates, got %1</source>
        <translation>控制点必须有 2 个或 3 个坐标，实际为 %1 个</translation>
    </message>
    <message>
        <source>%1 control points are too few: affine combinations in %2D need at least %3 that are not collinear</source>
        <translation>%1 个控制点太少：%2D 中的仿射组合至少需要 %3 个不共线的点</translation>
    </message>
    <message>
        <source>%1 control points are too few: affine combinations in %2D need at least %3 that are not coplanar</source>
        <translation>%1 个控制点太少：%2D 中的仿射组合至少需要 %3 个不共面的点</translation>
    </message>
    <message>
        <source>the control points are all collinear: they must span the plane to write every image point as their affine combination (000 eq. (5))</source>
        <translation>控制点全部共线：它们必须张成整个平面，才能将每个像点写成它们的仿射组合（000 eq. (5)）</translation>
    </message>
    <message>
        <source>the control points are all coplanar: they must span space to write every image point as their affine combination (000 eq. (5))</source>
        <translation>控制点全部共面：它们必须张成整个空间，才能将每个像点写成它们的仿射组合（000 eq. (5)）</translation>
    </message>
    <message>
        <source>the point has %1 coordinates, the control points have %2</source>
        <translation>该点有 %1 个坐标，而控制点有 %2 个</translation>
    </message>
    <message>
        <source>point</source>
        <translation>点</translation>
    </message>
    <message>
        <source>the IFS has no maps</source>
        <translation>该 IFS 没有映射</translation>
    </message>
    <message>
        <source>map f_%1 is not a map of %2D points like the control points</source>
        <translation>映射 f_%1 不是像控制点那样的 %2D 点的映射</translation>
    </message>
    <message>
        <source>map f_%1 (linear part)</source>
        <translation>映射 f_%1（线性部分）</translation>
    </message>
    <message>
        <source>map f_%1 (translation)</source>
        <translation>映射 f_%1（平移部分）</translation>
    </message>
    <message>
        <source>Koch curve with control points</source>
        <translation>带控制点的 Koch 曲线</translation>
    </message>
    <message>
        <source>Sierpinski gasket with control points</source>
        <translation>带控制点的 Sierpinski 垫片</translation>
    </message>
    <message>
        <source>%1 needs %2 control points in the plane, got %3 with %4 coordinates</source>
        <translation>%1 需要平面上的 %2 个控制点，实际为 %3 个具有 %4 个坐标的点</translation>
    </message>
    <message>
        <source>Bézier degree must be at least 1</source>
        <translation>Bézier 曲线的次数必须至少为 1</translation>
    </message>
    <message>
        <source>B-spline degree must be at least 1</source>
        <translation>B 样条的次数必须至少为 1</translation>
    </message>
    <message>
        <source>a B-spline of degree %1 needs at least %2 control points (%3 knots), got %4 knots</source>
        <translation>%1 次 B 样条至少需要 %2 个控制点（%3 个节点），实际为 %4 个节点</translation>
    </message>
    <message>
        <source>B-spline knot %1 is not a finite number</source>
        <translation>B 样条节点 %1 不是有限数</translation>
    </message>
    <message>
        <source>B-spline knots must be nondecreasing (knot %1)</source>
        <translation>B 样条节点必须单调不减（节点 %1）</translation>
    </message>
    <message>
        <source>B-spline knot vector has an empty domain</source>
        <translation>B 样条节点向量的定义域为空</translation>
    </message>
    <message>
        <source>an end-interpolating B-spline of degree %1 needs at least %2 control points</source>
        <translation>%1 次端点插值 B 样条至少需要 %2 个控制点</translation>
    </message>
    <message>
        <source>B-spline needs %1 control points, got %2</source>
        <translation>B 样条需要 %1 个控制点，实际为 %2 个</translation>
    </message>
    <message>
        <source>scheme %1: the dilation must be at least 2</source>
        <translation>细分格式 %1：伸缩因子必须至少为 2</translation>
    </message>
    <message>
        <source>scheme %1: the mask holds a non-finite weight</source>
        <translation>细分格式 %1：掩模含有非有限权值</translation>
    </message>
    <message>
        <source>scheme %1: the mask is empty</source>
        <translation>细分格式 %1：掩模为空</translation>
    </message>
    <message>
        <source>scheme %1: the mask entries of class (%2, %3) mod %4 sum to %5, not 1</source>
        <translation>细分格式 %1：同余类 (%2, %3) mod %4 的掩模元素之和为 %5，而不是 1</translation>
    </message>
    <message>
        <source>scheme %1: local subdivision matrix not closed</source>
        <translation>细分格式 %1：局部细分矩阵不封闭</translation>
    </message>
    <message>
        <source>scheme %1: the local subdivision matrix has no eigenvalue 1</source>
        <translation>细分格式 %1：局部细分矩阵没有特征值 1</translation>
    </message>
    <message>
        <source>scheme %1: the limit eigenvector sums to 0</source>
        <translation>细分格式 %1：极限特征向量之和为 0</translation>
    </message>
    <message>
        <source>box spline %1: its directions sum to an odd vector, so the mask has no lattice-point centre</source>
        <translation>箱样条 %1：其方向之和为奇向量，因此掩模的中心不在格点上</translation>
    </message>
    <message>
        <source>bicubic B-spline</source>
        <translation>双三次 B 样条</translation>
    </message>
    <message>
        <source>Loop (three-direction quartic box spline)</source>
        <translation>Loop（三向四次箱样条）</translation>
    </message>
    <message>
        <source>Kobbelt √3 (two rounds)</source>
        <translation>Kobbelt √3（两轮）</translation>
    </message>
    <message>
        <source>positive (edge rotated 90° counter-clockwise)</source>
        <translation>正向（边逆时针旋转 90°）</translation>
    </message>
    <message>
        <source>negative (edge rotated 90° clockwise)</source>
        <translation>负向（边顺时针旋转 90°）</translation>
    </message>
    <message>
        <source>constant</source>
        <comment>β sign</comment>
        <translation>常数</translation>
    </message>
    <message>
        <source>Positive normal: the edge vector P_i P_{i+1} rotated 90° counter-clockwise; negative: rotated clockwise. d_i = |P_i P_{i+1}| n_i. In the β signs (-1)^i, (-1)^(k+i), (-1)^(k+1), k is the level of the polygon being subdivided (the first step has k = 0) and i the 0-based index of the edge.</source>
        <translation>正法向：边向量 P_i P_{i+1} 逆时针旋转 90°；负法向：顺时针旋转。d_i = |P_i P_{i+1}| n_i。在 β 符号 (-1)^i、(-1)^(k+i)、(-1)^(k+1) 中，k 是正在细分的多边形的层级（第一步 k = 0），i 是边的索引（从 0 开始）。</translation>
    </message>
    <message>
        <source>p = %1: the normal-vector scheme needs p &gt;= 2 rules, one (α_j, β_j) pair each</source>
        <translation>p = %1：法向量格式需要 p &gt;= 2 条规则，每条规则一对 (α_j, β_j)</translation>
    </message>
    <message>
        <source>β has %1 values but α has %2: eq. (1) needs one (α_j, β_j) pair per rule j = 0..p-1</source>
        <translation>β 有 %1 个值而 α 有 %2 个：eq. (1) 要求每条规则 j = 0..p-1 有一对 (α_j, β_j)</translation>
    </message>
    <message>
        <source>α_%1 is not a finite number</source>
        <translation>α_%1 不是有限数</translation>
    </message>
    <message>
        <source>β_%1 is not a finite number</source>
        <translation>β_%1 不是有限数</translation>
    </message>
    <message>
        <source>%1 β signs given for p = %2 rules: give none, one for all rules, or one per rule</source>
        <translation>为 p = %2 条规则给出了 %1 个 β 符号：请不给出、为所有规则给出一个，或每条规则给出一个</translation>
    </message>
    <message>
        <source>p = %1, α = %2, β = %3, β signs (%4), normals %5</source>
        <translation>p = %1，α = %2，β = %3，β 符号 (%4)，法向 %5</translation>
    </message>
    <message>
        <source>the normal-vector scheme works in the plane: control points need 2 coordinates, got %1</source>
        <translation>法向量格式在平面上工作：控制点需要 2 个坐标，实际为 %1 个</translation>
    </message>
    <message>
        <source>control polygon</source>
        <translation>控制多边形</translation>
    </message>
    <message>
        <source>a closed control polygon needs at least %1 points, got %2</source>
        <translation>闭合控制多边形至少需要 %1 个点，实际为 %2 个</translation>
    </message>
    <message>
        <source>an open control polygon needs at least %1 points, got %2</source>
        <translation>开控制多边形至少需要 %1 个点，实际为 %2 个</translation>
    </message>
    <message>
        <source>open control polygons need α_0 = β_0 = 0: rule 0 at the last point (i = p^k n in eq. (1)) would use a point after the end; close the polygon instead</source>
        <translation>开控制多边形要求 α_0 = β_0 = 0：最后一个点处的规则 0（eq. (1) 中 i = p^k n）会用到末端之后的点；请改为闭合多边形</translation>
    </message>
    <message>
        <source>the number of subdivision steps cannot be negative, got %1</source>
        <translation>细分步数不能为负数，实际为 %1</translation>
    </message>
    <message>
        <source>the subdivision level cannot be negative, got %1</source>
        <translation>细分层级不能为负数，实际为 %1</translation>
    </message>
    <message>
        <source>%1 subdivision steps of a polygon with %2 edges would make %3 points (at most %4); use fewer steps</source>
        <translation>对有 %2 条边的多边形进行 %1 步细分将产生 %3 个点（最多 %4 个）；请减少步数</translation>
    </message>
    <message>
        <source>convergent: every edge shrinks by a factor of at most %1 per step, so ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (longest initial edge) and F^k is a Cauchy sequence (the argument of 001 Theorem 1); non-rectifiable: the polygon length grows by a factor of at least %3 per step (001 Theorem 2)</source>
        <translation>收敛：每一步每条边的长度至多变为原来的 %1 倍，因此 ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (最长初始边)，F^k 是 Cauchy 序列（001 Theorem 1 的论证）；不可求长：每一步多边形长度至少变为原来的 %3 倍（001 Theorem 2）</translation>
    </message>
    <message>
        <source>convergent: every edge shrinks by a factor of at most %1 per step, so ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (longest initial edge) and F^k is a Cauchy sequence (the argument of 001 Theorem 1)</source>
        <translation>收敛：每一步每条边的长度至多变为原来的 %1 倍，因此 ||F^{k+1} - F^k|| &lt;= %2 * %1^k * (最长初始边)，F^k 是 Cauchy 序列（001 Theorem 1 的论证）</translation>
    </message>
    <message>
        <source>not decided: the one-step edge bound is %1 &gt;= 1, so the argument of 001 Theorem 1 does not apply (see the measured edge lengths per level)</source>
        <translation>未判定：单步边长界为 %1 &gt;= 1，因此 001 Theorem 1 的论证不适用（请查看各层实测的边长）</translation>
    </message>
    <message>
        <source>α_0 and β_0 are not both 0: the new edge across each old vertex joins two old edges and is not the image of one edge, so no IFS of one similarity per new edge exists</source>
        <translation>α_0 与 β_0 不全为 0：跨过每个旧顶点的新边连接两条旧边，不是某一条边的像，因此不存在每条新边对应一个相似变换的 IFS</translation>
    </message>
    <message>
        <source>new edge %1 of the unit edge has length %2 &gt;= 1: no map would contract</source>
        <translation>单位边的新边 %1 的长度为 %2 &gt;= 1：没有映射是压缩的</translation>
    </message>
    <message>
        <source>no IFS of %1 similarities (each new edge taken forward or reversed, plain or mirrored: %2 patterns) reproduces the polygons of the first %3 steps; the β sign changes with the level, so the rules repeat only every two steps (an IFS would need p^2 maps)</source>
        <translation>由 %1 个相似变换组成的 IFS（每条新边取正向或反向、原样或镜像：共 %2 种模式）都无法再现前 %3 步的多边形；β 的符号随层级变化，因此规则每两步才重复一次（IFS 需要 p^2 个映射）</translation>
    </message>
    <message>
        <source>no IFS of %1 similarities (each new edge taken forward or reversed, plain or mirrored: %2 patterns) reproduces the polygons of the first %3 steps</source>
        <translation>由 %1 个相似变换组成的 IFS（每条新边取正向或反向、原样或镜像：共 %2 种模式）都无法再现前 %3 步的多边形</translation>
    </message>
    <message>
        <source>no equivalent IFS: %1</source>
        <translation>没有等价的 IFS：%1</translation>
    </message>
    <message>
        <source>edge %1 of the control polygon is subdivided with rules no similarity copy of the unit edge&apos;s limit reproduces</source>
        <translation>控制多边形的第 %1 条边所用的细分规则，无法由单位边极限的任何相似副本再现</translation>
    </message>
    <message>
        <source>Lévy C curve</source>
        <translation>Lévy C 曲线</translation>
    </message>
    <message>
        <source>binary interpolatory; new point at the apex of a right isosceles triangle</source>
        <translation>二进制插值；新点位于等腰直角三角形的顶点</translation>
    </message>
    <message>
        <source>Dragon curve</source>
        <translation>龙曲线</translation>
    </message>
    <message>
        <source>scheme (2) with β_1 = (-1)^i / 2: the bump alternates sides along the curve</source>
        <translation>格式 (2)，β_1 = (-1)^i / 2：凸起沿曲线交替位于两侧</translation>
    </message>
    <message>
        <source>Sierpiński gasket (arrowhead curve)</source>
        <translation>Sierpiński 垫片（箭头曲线）</translation>
    </message>
    <message>
        <source>non-stationary and non-uniform, as in the paper: β_1 = β_2 = (-1)^(k+i) √3/4 flips with the level k and the edge i; the polygons tend to the gasket</source>
        <translation>与论文一致，为非稳态且非均匀格式：β_1 = β_2 = (-1)^(k+i) √3/4 随层级 k 和边 i 翻转；多边形趋于该垫片</translation>
    </message>
    <message>
        <source>Koch curve</source>
        <translation>Koch 曲线</translation>
    </message>
    <message>
        <source>quaternary interpolatory; the limit is the classic Koch curve</source>
        <translation>四进制插值；极限为经典的 Koch 曲线</translation>
    </message>
    <message>
        <source>Koch snowflake</source>
        <translation>Koch 雪花</translation>
    </message>
    <message>
        <source>the triangle traversed counter-clockwise with negative normals, so every bump points outwards (NOTES.md)</source>
        <translation>三角形按逆时针方向遍历并使用负法向，因此每个凸起都朝外（NOTES.md）</translation>
    </message>
    <message>
        <source>Tigerhead-like curve</source>
        <translation>类虎头曲线</translation>
    </message>
    <message>
        <source>α = (0, -1/4, 1/2, 5/4), β = (0, 1/3, 1/2, 1/3): rules 1 and 3 lie outside the edge, so the curve overlaps itself</source>
        <translation>α = (0, -1/4, 1/2, 5/4)，β = (0, 1/3, 1/2, 1/3)：规则 1 和 3 位于边之外，因此曲线自身重叠</translation>
    </message>
    <message>
        <source>Human-like curve</source>
        <translation>类人形曲线</translation>
    </message>
    <message>
        <source>β = (-1)^(k+1) (0, 1/3, 1/2, 1/3): the bumps point down at the first step (k = 0) and flip at every level</source>
        <translation>β = (-1)^(k+1) (0, 1/3, 1/2, 1/3)：第一步（k = 0）时凸起朝下，之后每一层翻转一次</translation>
    </message>
    <message>
        <source>Approximating curve</source>
        <translation>逼近型曲线</translation>
    </message>
    <message>
        <source>α_0 = -1/2 moves the old points, so the polygon must be closed; the text does not give the quadrilateral of Fig. 3(c): a unit square traversed counter-clockwise is assumed</source>
        <translation>α_0 = -1/2 会移动旧点，因此多边形必须闭合；原文未给出 Fig. 3(c) 中的四边形：此处假定为按逆时针方向遍历的单位正方形</translation>
    </message>
    <message>
        <source>Crown-like curve</source>
        <translation>类王冠曲线</translation>
    </message>
    <message>
        <source>6-ary interpolatory</source>
        <translation>六进制插值</translation>
    </message>
    <message>
        <source>7-ary square-wave curve</source>
        <translation>七进制方波曲线</translation>
    </message>
    <message>
        <source>the paper calls it the Minkowski curve; it equals the Minkowski sausage only at level 1 (its middle edge has length 1/2 and is replaced by a half-size copy), so it is a different curve of similarity dimension log_2 3, not 1.5</source>
        <translation>论文称之为 Minkowski 曲线；它仅在第 1 层与 Minkowski 香肠相同（其中间边长为 1/2，并被替换为一半大小的副本），因此它是另一条曲线，相似维数为 log_2 3，而不是 1.5</translation>
    </message>
    <message>
        <source>unknown normal-vector preset %1</source>
        <translation>未知的法向量预设 %1</translation>
    </message>
    <message>
        <source>%1 needs exactly %2 control points, got %3</source>
        <translation>%1 恰好需要 %2 个控制点，实际为 %3 个</translation>
    </message>
    <message>
        <source>%1 needs at least %2 control points, got %3</source>
        <translation>%1 至少需要 %2 个控制点，实际为 %3 个</translation>
    </message>
    <message>
        <source>%1: the arity of a scheme must be at least 2, got %2</source>
        <translation>%1：细分格式的进制数必须至少为 2，实际为 %2</translation>
    </message>
    <message>
        <source>%1: a scheme of arity %2 needs %2 rules, got %3</source>
        <translation>%1：%2 进制细分格式需要 %2 条规则，实际为 %3 条</translation>
    </message>
    <message>
        <source>%1: rule %2 has no weights</source>
        <translation>%1：规则 %2 没有权值</translation>
    </message>
    <message>
        <source>%1: weight %2 of rule %3 is not a finite number</source>
        <translation>%1：规则 %3 的权值 %2 不是有限数</translation>
    </message>
    <message>
        <source>%1: the weights of rule %2 sum to %3, not 1 (an affine rule must reproduce constants)</source>
        <translation>%1：规则 %2 的权值之和为 %3，而不是 1（仿射规则必须再生常数）</translation>
    </message>
    <message>
        <source>B-spline degree must be between 1 and 15, got %1</source>
        <translation>B 样条的次数必须介于 1 和 15 之间，实际为 %1</translation>
    </message>
    <message>
        <source>uniform B-spline of degree %1</source>
        <translation>%1 次均匀 B 样条</translation>
    </message>
    <message>
        <source>corner cutting needs 0 &lt; a &lt; b &lt; 1, got a = %1, b = %2</source>
        <translation>割角要求 0 &lt; a &lt; b &lt; 1，实际为 a = %1，b = %2</translation>
    </message>
    <message>
        <source>corner cutting (%1, %2)</source>
        <translation>割角 (%1, %2)</translation>
    </message>
    <message>
        <source>four-point tension omega is not a finite number</source>
        <translation>四点格式的张力参数 omega 不是有限数</translation>
    </message>
    <message>
        <source>four-point (omega = %1)</source>
        <translation>四点格式（omega = %1）</translation>
    </message>
    <message>
        <source>Bézier degree must be between 1 and 30, got %1</source>
        <translation>Bézier 曲线的次数必须介于 1 和 30 之间，实际为 %1</translation>
    </message>
    <message>
        <source>the de Casteljau split parameter t must lie strictly between 0 and 1, got %1</source>
        <translation>de Casteljau 分割参数 t 必须严格介于 0 和 1 之间，实际为 %1</translation>
    </message>
    <message>
        <source>Bézier of degree %1 (de Casteljau at t = %2)</source>
        <translation>%1 次 Bézier 曲线（在 t = %2 处做 de Casteljau 分割）</translation>
    </message>
    <message>
        <source>end-interpolating B-spline of degree %1</source>
        <translation>%1 次端点插值 B 样条</translation>
    </message>
    <message>
        <source>%1: an IFS needs at least two matrices, got %2</source>
        <translation>%1：IFS 至少需要两个矩阵，实际为 %2 个</translation>
    </message>
    <message>
        <source>%1: matrix S_1 is empty</source>
        <translation>%1：矩阵 S_1 为空</translation>
    </message>
    <message>
        <source>%1: matrix S_%2 is %3 x %4, expected %5 x %5 like S_1</source>
        <translation>%1：矩阵 S_%2 为 %3 × %4，应与 S_1 一样为 %5 × %5</translation>
    </message>
    <message>
        <source>%1: matrix S_%2</source>
        <translation>%1：矩阵 S_%2</translation>
    </message>
    <message>
        <source>%1: matrix S_%2, row %3 sums to %4, not 1 (subdivision rows are affine combinations)</source>
        <translation>%1：矩阵 S_%2 的第 %3 行之和为 %4，而不是 1（细分矩阵的行是仿射组合）</translation>
    </message>
    <message>
        <source>the number of subdivision steps cannot be negative</source>
        <translation>细分步数不能为负数</translation>
    </message>
    <message>
        <source>classic subdivision with %1 steps would make %2 points; use fewer steps</source>
        <translation>%1 步经典细分将产生 %2 个点；请减少步数</translation>
    </message>
    <message>
        <source>user matrices</source>
        <translation>用户矩阵</translation>
    </message>
    <message>
        <source>the square lattice of %1 has no layout &apos;%2&apos; (it has: %3)</source>
        <translation>%1 的正方形格点没有布局“%2”（现有布局：%3）</translation>
    </message>
    <message>
        <source>the triangular lattice of %1 has no layout &apos;%2&apos; (it has: %3)</source>
        <translation>%1 的三角形格点没有布局“%2”（现有布局：%3）</translation>
    </message>
    <message>
        <source>%1: the mask is not symmetric under the turn of map %2 of the %3 layout</source>
        <translation>%1：在 %3 布局的映射 %2 的旋转下，掩模不对称</translation>
    </message>
    <message>
        <source>%1: the pieces of the %2 layout are not determined by a finite net</source>
        <translation>%1：%2 布局的各片段不能由有限控制网格确定</translation>
    </message>
    <message>
        <source>the patch needs %1 control points on its net, got %2</source>
        <translation>该曲面片的控制网格需要 %1 个控制点，实际为 %2 个</translation>
    </message>
    <message>
        <source>lattice point %1 is given twice (points %2 and %3)</source>
        <translation>格点 %1 重复给出（点 %2 和 %3）</translation>
    </message>
    <message>
        <source>lattice point %1 (point %2) is not on the square net of the patch; missing: %3</source>
        <translation>格点 %1（点 %2）不在曲面片的正方形网格上；缺少：%3</translation>
    </message>
    <message>
        <source>lattice point %1 (point %2) is not on the triangular net of the patch; missing: %3</source>
        <translation>格点 %1（点 %2）不在曲面片的三角形网格上；缺少：%3</translation>
    </message>
    <message>
        <source>the net has %1 lattice points but %2 control points</source>
        <translation>控制网格有 %1 个格点，但有 %2 个控制点</translation>
    </message>
    <message>
        <source>refinement rounds must be from 0 to 12, got %1</source>
        <translation>细化轮数必须在 0 到 12 之间，实际为 %1</translation>
    </message>
    <message>
        <source>the mesh was refined by another scheme</source>
        <translation>该网格由另一种细分格式细化</translation>
    </message>
    <message>
        <source>the arity of a mask must be between 2 and 64, got %1</source>
        <translation>掩模的元数必须介于 2 和 64 之间，实际为 %1</translation>
    </message>
    <message>
        <source>a mask needs between 1 and 4096 coefficients, got %1</source>
        <translation>掩模需要 1 到 4096 个系数，实际为 %1</translation>
    </message>
    <message>
        <source>the mask&apos;s offset %1 is absurd</source>
        <translation>掩模的偏移量 %1 不合理</translation>
    </message>
    <message>
        <source>mask coefficient %1 is not a finite number</source>
        <translation>掩模系数 %1 不是有限数</translation>
    </message>
    <message>
        <source>the coefficients a_k with k = %1 mod %2 sum to %3, not 1: every coset of the mask must sum to 1 (the scheme must reproduce constants; the whole mask sums to the arity %2)</source>
        <translation>满足 k = %1 mod %2 的系数 a_k 之和为 %3，而不是 1：掩模的每个陪集之和都必须为 1（格式必须再现常数；整个掩模之和为元数 %2）</translation>
    </message>
    <message>
        <source>mask of arity %1</source>
        <translation>元数为 %1 的掩模</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Subdivision curves as attractors of IFS.</source>
        <translation>作为 IFS 吸引子的细分曲线。</translation>
    </message>
    <message>
        <source>Project file to open.</source>
        <translation>要打开的项目文件。</translation>
    </message>
    <message>
        <source>Select the item with this name after opening.</source>
        <translation>打开后选择具有此名称的对象。</translation>
    </message>
    <message>
        <source>Print the current item&apos;s figure sheet to this PDF file, then quit.</source>
        <translation>将当前对象的图形页打印到此 PDF 文件，然后退出。</translation>
    </message>
    <message>
        <source>Save a picture of the main window to this PNG file once the attractor is drawn, then quit.</source>
        <translation>绘制完吸引子后，将主窗口的图片保存到此 PNG 文件，然后退出。</translation>
    </message>
    <message>
        <source>Window size for --screenshot, WIDTHxHEIGHT.</source>
        <translation>--screenshot 的窗口尺寸，格式为 WIDTHxHEIGHT。</translation>
    </message>
    <message>
        <source>Export a figure of the current item to this file (.png, .svg, .pdf; .tex for the matrices), then quit.</source>
        <translation>将当前对象的图形导出到此文件（.png、.svg、.pdf；矩阵使用 .tex），然后退出。</translation>
    </message>
    <message>
        <source>Resolution of --export-figure in dpi (36..2400).</source>
        <translation>--export-figure 的分辨率，单位为 dpi（36..2400）。</translation>
    </message>
    <message>
        <source>What --export-figure shows: attractor, spectrum, matrices, analysis or sheet.</source>
        <translation>--export-figure 显示的内容：attractor、spectrum、matrices、analysis 或 sheet。</translation>
    </message>
    <message>
        <source>Size of --export-figure in pixels at its resolution, WIDTHxHEIGHT (16..20000).</source>
        <translation>--export-figure 在其分辨率下的像素尺寸，格式为 WIDTHxHEIGHT（16..20000）。</translation>
    </message>
    <message>
        <source>--export-figure without the grid.</source>
        <translation>--export-figure 不绘制网格线。</translation>
    </message>
    <message>
        <source>--export-figure without control polygons and start set.</source>
        <translation>--export-figure 不绘制控制多边形和初始集。</translation>
    </message>
    <message>
        <source>--export-figure framed tightly around the content (the height follows its proportions).</source>
        <translation>--export-figure 紧贴内容裁剪边框（高度按内容比例确定）。</translation>
    </message>
    <message>
        <source>Font of --export-figure&apos;s labels: FAMILY or FAMILY,POINTS.</source>
        <translation>--export-figure 标签所用的字体：FAMILY 或 FAMILY,POINTS。</translation>
    </message>
</context>
</TS>
