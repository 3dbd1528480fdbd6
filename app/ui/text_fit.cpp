#include "ui/text_fit.hpp"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>

namespace springlab::ui {

namespace {

// How much two glyphs may share (antialiasing, kerning) and a glyph may pass its clip (the
// rounding of its place) before it is a fault, in pixels.
constexpr float kTolerance = 1.5f;

struct GlyphKey {
  float u0, v0, u1, v1;
  bool operator<(const GlyphKey& o) const {
    return std::tie(u0, v0, u1, v1) < std::tie(o.u0, o.v0, o.u1, o.v1);
  }
};

std::string utf8(unsigned int c) {
  std::string s;
  if (c < 0x80)
    s += static_cast<char>(c);
  else if (c < 0x800)
    s += static_cast<char>(0xC0 | (c >> 6)), s += static_cast<char>(0x80 | (c & 0x3F));
  else if (c < 0x10000)
    s += static_cast<char>(0xE0 | (c >> 12)), s += static_cast<char>(0x80 | ((c >> 6) & 0x3F)),
        s += static_cast<char>(0x80 | (c & 0x3F));
  else
    s += static_cast<char>(0xF0 | (c >> 18)), s += static_cast<char>(0x80 | ((c >> 12) & 0x3F)),
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F)), s += static_cast<char>(0x80 | (c & 0x3F));
  return s;
}

struct Known {
  unsigned int codepoint;
  float y0, y1;          // the glyph's top and bottom below its line's top, in its font's pixels
  float font_size;       // its line's height
  float u0, v0, u1, v1;  // its corner of the atlas
};

// The glyphs by their corner of the atlas; and, for a glyph Dear ImGui cut to its clip on the CPU
// (its quad and its texture coordinates both shortened: a combo's preview, a label at a panel's
// edge), the glyph whose corner holds the cut one's (the atlas's glyphs never overlap), found
// through a grid of the atlas.
class Atlas {
 public:
  explicit Atlas(const ImFontAtlas& fonts) {
    for (const ImFont* font : fonts.Fonts)
      for (const ImFontGlyph& g : font->Glyphs)
        if (g.Visible) {
          const Known k{g.Codepoint, g.Y0, g.Y1, font->FontSize, g.U0, g.V0, g.U1, g.V1};
          if (!exact_.emplace(GlyphKey{g.U0, g.V0, g.U1, g.V1}, k).second) continue;
          for (int y = cell(g.V0); y <= cell(g.V1); ++y)
            for (int x = cell(g.U0); x <= cell(g.U1); ++x) grid_[y * kCells + x].push_back(k);
        }
  }
  const Known* exact(const GlyphKey& uv) const {
    const auto found = exact_.find(uv);
    return found == exact_.end() ? nullptr : &found->second;
  }
  const Known* holding(const GlyphKey& uv) const {
    const float u = 0.5f * (uv.u0 + uv.u1), v = 0.5f * (uv.v0 + uv.v1);
    for (const Known& k : grid_[cell(v) * kCells + cell(u)])
      if (uv.u0 >= k.u0 - 1e-6f && uv.u1 <= k.u1 + 1e-6f && uv.v0 >= k.v0 - 1e-6f &&
          uv.v1 <= k.v1 + 1e-6f)
        return &k;
    return nullptr;
  }

 private:
  static constexpr int kCells = 64;
  static int cell(float t) { return std::clamp(static_cast<int>(t * kCells), 0, kCells - 1); }
  std::map<GlyphKey, Known> exact_;
  std::vector<std::vector<Known>> grid_ = std::vector<std::vector<Known>>(kCells * kCells);
};

// The whole quad of a glyph drawn cut: its quad stretched back by the texture coordinates it lost,
// at the pixels a unit of them spans.
ImVec4 uncut(const ImDrawVert* v, const Known& g) {
  const float du = v[2].uv.x - v[0].uv.x, dv = v[2].uv.y - v[0].uv.y;
  const float sx = du > 0 ? (v[2].pos.x - v[0].pos.x) / du : 0.0f;
  const float sy = dv > 0 ? (v[2].pos.y - v[0].pos.y) / dv : 0.0f;
  return ImVec4(v[0].pos.x - (v[0].uv.x - g.u0) * sx, v[0].pos.y - (v[0].uv.y - g.v0) * sy,
                v[2].pos.x + (g.u1 - v[2].uv.x) * sx, v[2].pos.y + (g.v1 - v[2].uv.y) * sy);
}

// The scale a glyph is drawn at (a window's font scale), its line's top and its line's height.
struct Placed {
  float scale, top, size;
};
Placed placed(const ImVec4& quad, const Known& g) {
  const float scale = g.y1 > g.y0 ? (quad.w - quad.y) / (g.y1 - g.y0) : 1.0f;
  return {scale, quad.y - g.y0 * scale, g.font_size * scale};
}

bool meets(const ImVec4& a, const ImVec4& b, float by) {
  return std::min(a.z, b.z) - std::max(a.x, b.x) > by &&
         std::min(a.w, b.w) - std::max(a.y, b.y) > by;
}

ImVec4 clipped(const ImVec4& a, const ImVec4& clip) {
  return ImVec4(std::max(a.x, clip.x), std::max(a.y, clip.y), std::min(a.z, clip.z),
                std::min(a.w, clip.w));
}

std::string quoted(const std::string& text) {
  std::string s = text.size() > 60 ? text.substr(0, 57) + "..." : text;
  return "'" + s + "'";
}

}  // namespace

std::vector<TextRun> text_runs(const ImDrawData& data, const ImFontAtlas& fonts) {
  // Each glyph's corner of the atlas, for every font (the CJK glyphs are merged into them).
  const Atlas atlas(fonts);
  std::vector<TextRun> runs;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      if (cmd.UserCallback) continue;
      TextRun* run = nullptr;
      ImVec4 last{0, 0, 0, 0};
      float last_top = 0.0f, last_size = 0.0f;
      for (unsigned int i = 0; i + 5 < cmd.ElemCount; i += 3) {
        const ImDrawIdx* idx = list.IdxBuffer.Data + cmd.IdxOffset + i;
        // A glyph: two triangles (a, a+1, a+2) and (a, a+2, a+3) whose corners are its atlas
        // corners.
        const unsigned int a = idx[0] + cmd.VtxOffset;
        if (idx[1] != idx[0] + 1 || idx[2] != idx[0] + 2 || idx[3] != idx[0] ||
            idx[4] != idx[0] + 2 || idx[5] != idx[0] + 3 ||
            a + 3 >= static_cast<unsigned int>(list.VtxBuffer.Size))
          continue;
        const ImDrawVert* v = list.VtxBuffer.Data + a;
        if (v[1].uv.x != v[2].uv.x || v[1].uv.y != v[0].uv.y || v[3].uv.x != v[0].uv.x) continue;
        const GlyphKey uv{v[0].uv.x, v[0].uv.y, v[2].uv.x, v[2].uv.y};
        const Known* exact = atlas.exact(uv);
        const bool cut_glyph = !exact && cmd.TextureId == fonts.TexID && uv.u1 > uv.u0 &&
                               uv.v1 > uv.v0;  // (not the white pixel other shapes use)
        const Known* found = exact ? exact : cut_glyph ? atlas.holding(uv) : nullptr;
        if (!found) continue;
        i += 3;  // (the glyph's second triangle)
        const Known& g = *found;
        const ImVec4 quad =
            exact ? ImVec4(v[0].pos.x, v[0].pos.y, v[2].pos.x, v[2].pos.y) : uncut(v, g);
        const Placed p = placed(quad, g);
        const float top = p.top, size = p.size;
        // The same run: the same line, the pen moved on from the last glyph, and not far.
        const bool same = run && std::abs(top - last_top) < 0.3f * std::max(size, last_size) &&
                          quad.x >= last.z - kTolerance &&
                          quad.x <= last.z + 1.5f * std::max(size, last_size);
        if (!same) {
          runs.push_back(TextRun{});
          run = &runs.back();
          run->clip = cmd.ClipRect;
          run->box = quad;
          run->list = l;
        } else if (quad.x - last.z > 0.2f * size) {
          run->text += ' ';
        }
        run->text += utf8(g.codepoint);
        run->glyphs.push_back(quad);
        run->cut = run->cut || !exact;
        run->box = ImVec4(std::min(run->box.x, quad.x), std::min(run->box.y, quad.y),
                          std::max(run->box.z, quad.z), std::max(run->box.w, quad.w));
        last = quad, last_top = top, last_size = size;
      }
    }
  }
  return runs;
}

Windows windows_of(const ImDrawData& data) {
  Windows out;
  const ImGuiContext* g = ImGui::GetCurrentContext();
  if (!g) return out;
  for (const ImGuiWindow* w : g->Windows) {
    if (!w->Active) continue;
    const ImVec4 inner(w->InnerClipRect.Min.x, w->InnerClipRect.Min.y, w->InnerClipRect.Max.x,
                       w->InnerClipRect.Max.y);
    if (w->ScrollbarY) out.scrolling.push_back(inner);
    const ImGuiCol bg = (w->Flags & ImGuiWindowFlags_ChildWindow) ? ImGuiCol_ChildBg
                        : (w->Flags & (ImGuiWindowFlags_Popup | ImGuiWindowFlags_Tooltip))
                            ? ImGuiCol_PopupBg
                            : ImGuiCol_WindowBg;
    if ((w->Flags & ImGuiWindowFlags_NoBackground) || g->Style.Colors[bg].w < 0.85f) continue;
    for (int l = 0; l < data.CmdListsCount; ++l)
      if (data.CmdLists[l] == w->DrawList)
        out.covers.push_back(
            {ImVec4(w->Pos.x, w->Pos.y, w->Pos.x + w->Size.x, w->Pos.y + w->Size.y), l});
  }
  return out;
}

namespace {

// What is seen: each run's glyphs not under a window drawn after it.
std::vector<TextRun> seen_runs(const std::vector<TextRun>& all, const Windows& windows) {
  std::vector<TextRun> runs;
  for (const TextRun& run : all) {
    TextRun seen = run;
    seen.glyphs.clear();
    for (const ImVec4& g : run.glyphs) {
      const ImVec2 centre(0.5f * (g.x + g.z), 0.5f * (g.y + g.w));
      const bool hidden =
          std::any_of(windows.covers.begin(), windows.covers.end(), [&](const Windows::Cover& c) {
            return c.list > run.list && centre.x >= c.rect.x && centre.x <= c.rect.z &&
                   centre.y >= c.rect.y && centre.y <= c.rect.w;
          });
      if (!hidden) seen.glyphs.push_back(g);
    }
    if (seen.glyphs.empty()) continue;
    seen.box = seen.glyphs.front();
    for (const ImVec4& g : seen.glyphs)
      seen.box = ImVec4(std::min(seen.box.x, g.x), std::min(seen.box.y, g.y),
                        std::max(seen.box.z, g.z), std::max(seen.box.w, g.w));
    runs.push_back(std::move(seen));
  }
  return runs;
}

}  // namespace

std::vector<std::string> text_faults(const std::vector<TextRun>& all, const Windows& windows) {
  const std::vector<TextRun> runs = seen_runs(all, windows);
  const std::vector<ImVec4>& scrolling = windows.scrolling;
  std::vector<std::string> faults;
  char s[400];
  // Cut: a glyph partly out of its clip rectangle (one wholly out is not drawn at all); shortened:
  // an ellipsis.
  for (const TextRun& run : runs) {
    for (const ImVec4& g : run.glyphs) {
      const ImVec4& c = run.clip;
      if (!meets(g, c, 0.0f)) continue;
      // (A developer's report, printed by `render --check-text`: English only.)
      // not shown
      const char* side = g.z > c.z + kTolerance   ? "right"
                         : g.x < c.x - kTolerance ? "left"
                         : g.w > c.w + kTolerance ? "bottom"
                         : g.y < c.y - kTolerance ? "top"
                                                  : nullptr;
      if (!side) continue;
      // (In a window that scrolls, a row half in view at its top or foot is how scrolling looks.)
      const bool vertical = side[0] == 'b' || side[0] == 't';
      const auto inside = [&](const ImVec4& a) {
        return c.x >= a.x - 1 && c.y >= a.y - 1 && c.z <= a.z + 1 && c.w <= a.w + 1;
      };
      if (vertical && std::any_of(scrolling.begin(), scrolling.end(), inside)) continue;
      // not shown
      std::snprintf(s, sizeof s,
                    "%s is cut at its %s by its widget's edge (%.0f, %.0f to %.0f, %.0f)",
                    quoted(run.text).c_str(), side, c.x, c.y, c.z, c.w);
      faults.push_back(s);
      break;
    }
    if (run.cut)  // (a developer's report: English only) not shown
      faults.push_back(quoted(run.text) +
                       " is cut by its widget's own edge (a glyph drawn in part)");
    if (run.text.find("\u2026") != std::string::npos)
      faults.push_back(quoted(run.text) + " is shortened (an ellipsis)");
  }
  // Over one another: a glyph of one run on a glyph of another, where both are drawn (in their
  // clips).
  std::set<std::pair<std::size_t, std::size_t>> said;
  for (std::size_t i = 0; i < runs.size(); ++i)
    for (std::size_t j = i + 1; j < runs.size(); ++j) {
      if (!meets(runs[i].box, runs[j].box, kTolerance)) continue;
      for (const ImVec4& a : runs[i].glyphs) {
        const ImVec4 ca = clipped(a, runs[i].clip);
        bool hit = false;
        for (const ImVec4& b : runs[j].glyphs) {
          const ImVec4 cb = clipped(b, runs[j].clip);
          if (!meets(ca, cb, kTolerance)) continue;
          // not shown
          std::snprintf(s, sizeof s, "%s overlaps %s at (%.0f, %.0f)", quoted(runs[i].text).c_str(),
                        quoted(runs[j].text).c_str(), std::max(ca.x, cb.x), std::max(ca.y, cb.y));
          if (said.emplace(i, j).second) faults.push_back(s);
          hit = true;
          break;
        }
        if (hit) break;
      }
    }
  return faults;
}

}  // namespace springlab::ui
