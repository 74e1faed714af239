#include "grading/page_parts.h"

#include "grading/grade_outputs.h"

#include <cstdio>

namespace m3055::grading::page {

std::string escape_html(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string score_text(double value) {
    char out[64];
    std::snprintf(out, sizeof out, "%.6g", value);
    return out;
}

const char* const kStyle = R"(<style>
body{font-family:sans-serif;margin:1em;color:#111}
table{border-collapse:collapse;width:100%}
th,td{border:1px solid #999;padding:4px 6px;vertical-align:top;text-align:left}
th{background:#eee;cursor:pointer}
td.num{text-align:right;white-space:nowrap}
td.name{overflow-wrap:anywhere;word-break:break-word;max-width:12em;min-width:6em}
td.check{white-space:nowrap;text-align:center}td.check.ok{color:#060}td.check.no{color:#a00;background:#fdecec}
#summary table{width:auto}#summary td,#summary th{cursor:auto}
#controls{margin:0.8em 0}#controls input{width:18em}
tr.hidden{display:none}
#grades img{width:112px}#grades{font-size:92%}#grades td,#grades th{padding:3px 4px}
.swatch{display:inline-block;width:0.8em;height:0.8em;border:1px solid #666;vertical-align:middle;margin:0 1px 0 4px}
#grades th,td.check{font-size:85%}#grades th{overflow-wrap:normal;word-break:normal}#grades th:first-child{min-width:6em}
#grades td.reasons{min-width:11em}li.note{max-height:3.8em;overflow-y:auto}
li,code,figcaption,p,h1,h2{overflow-wrap:anywhere}td.result{white-space:nowrap}
img{width:256px;height:auto;image-rendering:pixelated;display:block}
.pass{color:#060;font-weight:bold}.fail,.refused{color:#a00;font-weight:bold}.missing{color:#555;font-weight:bold}.note{color:#555;font-style:italic}
ul{margin:0;padding-left:1.2em}
#top{display:flex;flex-wrap:wrap;gap:1.5em;align-items:flex-start}#top figcaption{font-size:90%;color:#444}#top figure{margin:0}
#histogram svg{display:block;max-width:100%;height:auto}
#grades img,.shots img{cursor:zoom-in}
#viewer{position:fixed;inset:0;background:rgba(20,20,20,0.92);color:#fff;display:flex;flex-direction:column;align-items:center;justify-content:center;z-index:10}
#viewer[hidden]{display:none}
#viewer img{width:auto;height:auto;image-rendering:pixelated;cursor:zoom-out;box-shadow:0 0 0 1px #888}
#viewer .bar{margin:0.6em;display:flex;gap:0.5em;align-items:center;flex-wrap:wrap;justify-content:center}
#viewer button{font-size:100%;padding:0.3em 0.8em;cursor:pointer}#viewer button[aria-pressed=true]{background:#ffd54a;font-weight:bold}
#viewer-title{font-weight:bold;overflow-wrap:anywhere;max-width:90vw}
@media print{#viewer{display:none}th{cursor:auto}tr{break-inside:avoid}img{width:200px}body{margin:0}}
</style>
)";

// The magnifier of both pages: a click on a render (or on the reference or a
// difference) shows it at the largest whole magnification that fits the
// window, nearest-neighbour (image-rendering: pixelated: every dot of the
// M3055's 512 x 320 display a square), and the buttons or keys 1 2 3 (r f d,
// arrows, space) flip between that student's render, the reference and the
// difference in place; Esc or a click on the picture closes it. The images
// are the page's own (data: URIs), so the page stays one file.
const char* const kViewer = R"(<div id="viewer" hidden role="dialog" aria-label="magnified view">
<div id="viewer-title"></div>
<div class="bar"><button type="button" data-kind="render">1 / r: render</button><button type="button" data-kind="reference">2 / f: reference</button><button type="button" data-kind="diff">3 / d: difference</button><span id="viewer-scale"></span><button type="button" id="viewer-close">Esc: close</button></div>
<img id="viewer-img" alt="">
</div>
<script>
(function(){
var v=document.getElementById('viewer'),img=document.getElementById('viewer-img'),shots={},kind='render',order=['render','reference','diff'];
var names={render:'render',reference:'the reference',diff:'levels off the reference'},title='';
function ref(){var r=document.getElementById('reference-image');return r?r.src:'';}
function fit(){var w=img.naturalWidth,h=img.naturalHeight;if(!w||!h)return;
var used=document.getElementById('viewer-title').offsetHeight+v.querySelector('.bar').offsetHeight+32;
var k=Math.max(1,Math.floor(Math.min((window.innerWidth-32)/w,(window.innerHeight-used)/h)));
img.style.width=(w*k)+'px';img.style.height=(h*k)+'px';document.getElementById('viewer-scale').textContent='\u00d7'+k;}
function show(k){if(!shots[k])return;kind=k;img.onload=fit;img.src=shots[k];img.alt=title+': '+names[k];
document.getElementById('viewer-title').textContent=title+' \u2014 '+names[k];
[].forEach.call(v.querySelectorAll('button[data-kind]'),function(b){b.setAttribute('aria-pressed',b.dataset.kind===k);b.disabled=!shots[b.dataset.kind];});
if(img.complete)fit();}
function open(row,k){shots={reference:ref()};title=row?row.dataset.student:'';
if(row)[].forEach.call(row.querySelectorAll('img[data-view]'),function(i){shots[i.dataset.view]=i.src;});
v.hidden=false;show(shots[k]?k:'reference');}
function close(){v.hidden=true;img.removeAttribute('src');}
window.m3055view=open;
document.addEventListener('click',function(e){var t=e.target;
if(t.matches&&t.matches('img[data-view]')&&!v.contains(t)){var row=t.closest('[data-student]');open(row,t.dataset.view);}
else if(t===img||t.id==='viewer-close'||t===v)close();
else if(t.dataset&&t.dataset.kind&&v.contains(t))show(t.dataset.kind);});
document.addEventListener('keydown',function(e){if(v.hidden)return;var k=e.key,i=order.indexOf(kind);
var to={'1':'render','r':'render','2':'reference','f':'reference','3':'diff','d':'diff'}[k];
if(k==='Escape')close();else if(to)show(to);
else if(k==='ArrowRight'||k===' '){do{i=(i+1)%3;}while(!shots[order[i]]);show(order[i]);}
else if(k==='ArrowLeft'){do{i=(i+2)%3;}while(!shots[order[i]]);show(order[i]);}else return;e.preventDefault();});
window.addEventListener('resize',function(){if(!v.hidden)fit();});
})();
</script>
)";

std::string inline_image_cell(const std::vector<std::uint8_t>& png, const std::string& alt, const char* view) {
    if (png.empty()) return "<td>&mdash;</td>";
    return "<td><img alt=\"" + escape_html(alt) + "\" data-view=\"" + view + "\" title=\"click to magnify\" "
           "src=\"data:image/png;base64," + base64(png) + "\"></td>";
}

std::string url_path(const std::string& relative) {
    std::string out;
    for (const char c : relative) {
        const unsigned char u = static_cast<unsigned char>(c);
        if ((u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') || c == '-' || c == '.' ||
            c == '_' || c == '~' || c == '/') {
            out += c;
            continue;
        }
        char escaped[4];
        std::snprintf(escaped, sizeof escaped, "%%%02X", unsigned(u));
        out += escaped;
    }
    return out;
}

}  // namespace m3055::grading::page
