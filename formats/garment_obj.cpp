#include "garment_obj.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "mesh/connected_components.h"
#include "text_numbers.h"

namespace foldsketch {
namespace {

struct Corner {
  int v, vt;
};
struct ObjFace {
  std::array<Corner, 3> corners;
  int group;  // -1: before any g/o line
  int line;
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) tokens.push_back(line.substr(i, j - i));
    i = j;
  }
  return tokens;
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

class ObjParser {
public:
  explicit ObjParser(std::string path) : path_(std::move(path)) {}

  Garment parse(std::istream& in) {
    std::string raw;
    while (std::getline(in, raw)) {
      ++line_;
      if (!raw.empty() && raw.back() == '\r') raw.pop_back();
      parse_line(raw);
    }
    if (in.bad()) fail(0, "read error");
    return build();
  }

private:
  [[noreturn]] void fail(int line, const std::string& message) const { throw InputError(path_, line, message); }

  double number(std::string_view token, const char* what) const {
    const auto x = parse_double(token);
    if (!x) fail(line_, std::string("expected a number for ") + what + ", found '" + std::string(token) + "'");
    if (!std::isfinite(*x)) fail(line_, std::string("non-finite ") + what + " '" + std::string(token) + "'");
    return *x;
  }

  // A 1-based or negative (relative) OBJ index into a list of `count` items so far.
  int index(std::string_view token, int count, const char* what, std::string_view corner) const {
    const auto i = parse_integer(token);
    if (!i || *i == 0)
      fail(line_, std::string("bad ") + what + " index '" + std::string(token) + "' in face corner '" + std::string(corner) + "'");
    if (*i < 0) {
      if (-*i > count) fail(line_, std::string(what) + " index " + std::string(token) + " reaches before the first " + what);
      return count + static_cast<int>(*i);
    }
    if (*i > (1LL << 30)) fail(line_, std::string(what) + " index '" + std::string(token) + "' is out of range");
    return static_cast<int>(*i) - 1;  // checked against the final count in build()
  }

  void parse_line(const std::string& raw) {
    const auto tokens = split(raw);
    if (tokens.empty() || tokens[0].front() == '#') return;
    const std::string_view key = tokens[0];
    if (key == "v") {
      if (tokens.size() < 4) fail(line_, "a v line needs 3 coordinates, found " + std::to_string(tokens.size() - 1));
      drape_.push_back({number(tokens[1], "x coordinate"), number(tokens[2], "y coordinate"), number(tokens[3], "z coordinate")});
    } else if (key == "vt") {
      if (tokens.size() < 3) fail(line_, "a vt line needs 2 coordinates, found " + std::to_string(tokens.size() - 1));
      pattern_.push_back({number(tokens[1], "u coordinate"), number(tokens[2], "v coordinate")});
    } else if (key == "g" || key == "o") {
      std::string name(trimmed(std::string_view(raw).substr(raw.find(key) + key.size())));
      if (name.empty()) name = "default";
      const auto it = std::find(groups_.begin(), groups_.end(), name);
      group_ = static_cast<int>(it - groups_.begin());
      if (it == groups_.end()) groups_.push_back(name);
    } else if (key == "f") {
      if (tokens.size() < 4) fail(line_, "a face needs at least 3 corners, found " + std::to_string(tokens.size() - 1));
      std::vector<Corner> corners;
      for (size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view c = tokens[k];
        const size_t slash = c.find('/');
        if (slash == std::string_view::npos || slash + 1 >= c.size() || c[slash + 1] == '/')
          fail(line_, "face corner '" + std::string(c) + "' has no vt index: every corner needs its pattern position (f v/vt)");
        const size_t slash2 = c.find('/', slash + 1);
        const std::string_view vt = c.substr(slash + 1, slash2 == std::string_view::npos ? std::string_view::npos : slash2 - slash - 1);
        corners.push_back({index(c.substr(0, slash), static_cast<int>(drape_.size()), "v", c),
                           index(vt, static_cast<int>(pattern_.size()), "vt", c)});
        ++corner_count_;
      }
      for (size_t k = 1; k + 1 < corners.size(); ++k) faces_.push_back({{corners[0], corners[k], corners[k + 1]}, group_, line_});
    }
    // Other statements (vn, vv, t, s, l, usemtl, mtllib, ...) carry nothing a garment needs.
  }

  Garment build() {
    if (faces_.empty()) fail(0, "no faces: a garment needs triangles (f v/vt lines)");
    for (const ObjFace& f : faces_)
      for (const Corner& c : f.corners) {
        if (c.v >= static_cast<int>(drape_.size()))
          fail(f.line, "face refers to v " + std::to_string(c.v + 1) + " but the file has " + std::to_string(drape_.size()) + " v lines");
        if (c.vt >= static_cast<int>(pattern_.size()))
          fail(f.line, "face refers to vt " + std::to_string(c.vt + 1) + " but the file has " + std::to_string(pattern_.size()) + " vt lines");
      }
    merge_corner_vts();

    Garment g;
    g.V.resize(static_cast<Eigen::Index>(drape_.size()), 3);
    for (size_t i = 0; i < drape_.size(); ++i) g.V.row(static_cast<Eigen::Index>(i)) << drape_[i][0], drape_[i][1], drape_[i][2];
    g.P.resize(static_cast<Eigen::Index>(pattern_.size()), 2);
    for (size_t i = 0; i < pattern_.size(); ++i) g.P.row(static_cast<Eigen::Index>(i)) << pattern_[i][0], pattern_[i][1];

    // Each pattern vertex belongs to one drape vertex.
    std::vector<int> drape_of(pattern_.size(), -1), first_line(pattern_.size(), 0);
    for (const ObjFace& f : faces_)
      for (const Corner& c : f.corners) {
        if (drape_of[c.vt] >= 0 && drape_of[c.vt] != c.v)
          fail(f.line, "vt " + std::to_string(c.vt + 1) + " is used with v " + std::to_string(c.v + 1) + " here and with v " +
                           std::to_string(drape_of[c.vt] + 1) + " on line " + std::to_string(first_line[c.vt]) +
                           ": a pattern vertex belongs to one drape vertex");
        drape_of[c.vt] = c.v;
        first_line[c.vt] = f.line;
      }

    // Panels: the groups, or connected components in pattern space when there are none.
    const int nF = static_cast<int>(faces_.size());
    MatrixX3i F(nF, 3), FP(nF, 3);
    for (int f = 0; f < nF; ++f)
      for (int k = 0; k < 3; ++k) {
        F(f, k) = faces_[f].corners[k].v;
        FP(f, k) = faces_[f].corners[k].vt;
      }
    std::vector<int> panel(nF);
    std::vector<std::string> names;
    const bool grouped = std::any_of(faces_.begin(), faces_.end(), [](const ObjFace& f) { return f.group >= 0; });
    if (grouped) {
      std::map<int, int> panel_of_group;  // in order of first face
      for (int f = 0; f < nF; ++f) {
        auto [it, added] = panel_of_group.try_emplace(faces_[f].group, static_cast<int>(names.size()));
        if (added) names.push_back(faces_[f].group >= 0 ? groups_[faces_[f].group] : "default");
        panel[f] = it->second;
      }
      std::vector<int> panel_of_vt(pattern_.size(), -1);
      for (int f = 0; f < nF; ++f)
        for (const Corner& c : faces_[f].corners) {
          if (panel_of_vt[c.vt] >= 0 && panel_of_vt[c.vt] != panel[f])
            fail(faces_[f].line, "vt " + std::to_string(c.vt + 1) + " is used by panels '" + names[panel_of_vt[c.vt]] +
                                     "' and '" + names[panel[f]] + "': panels share drape vertices (v), never vt");
          panel_of_vt[c.vt] = panel[f];
        }
    } else {
      const VectorXi components = face_components(FP, static_cast<int>(pattern_.size()));
      for (int f = 0; f < nF; ++f) panel[f] = components(f);
      for (int p = 0; p <= components.maxCoeff(); ++p) names.push_back("panel-" + std::to_string(p + 1));
    }
    std::vector<int> order(nF);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return panel[a] < panel[b]; });
    g.F.resize(nF, 3);
    g.FP.resize(nF, 3);
    g.face_panel.resize(nF);
    for (int i = 0; i < nF; ++i) {
      g.F.row(i) = F.row(order[i]);
      g.FP.row(i) = FP.row(order[i]);
      g.face_panel(i) = panel[order[i]];
    }
    for (const std::string& n : names) g.panels.push_back({n});
    return g;
  }

  // ARCSim / BGL files give every face corner its own vt. When every vt is used exactly once
  // and some corners repeat a (v, vt value) pair, merge those: the pair is one pattern vertex.
  void merge_corner_vts() {
    std::vector<int> uses(pattern_.size(), 0);
    for (const ObjFace& f : faces_)
      for (const Corner& c : f.corners) ++uses[c.vt];
    // Fan-triangulated polygons reuse their first corner; count corners as written instead.
    if (corner_count_ != pattern_.size() || std::any_of(uses.begin(), uses.end(), [](int u) { return u > 1; })) return;
    std::map<std::tuple<int, double, double>, int> merged;
    std::vector<std::array<double, 2>> kept;
    std::vector<int> new_index(pattern_.size(), -1);
    bool repeats = false;
    for (ObjFace& f : faces_)
      for (Corner& c : f.corners) {
        const auto key = std::make_tuple(c.v, pattern_[c.vt][0], pattern_[c.vt][1]);
        auto [it, added] = merged.try_emplace(key, static_cast<int>(kept.size()));
        if (added) kept.push_back(pattern_[c.vt]);
        else repeats = true;
        new_index[c.vt] = it->second;
      }
    if (!repeats) return;
    for (ObjFace& f : faces_)
      for (Corner& c : f.corners) c.vt = new_index[c.vt];
    pattern_ = std::move(kept);
  }

  std::string path_;
  int line_ = 0;
  int group_ = -1;
  size_t corner_count_ = 0;
  std::vector<std::array<double, 3>> drape_;
  std::vector<std::array<double, 2>> pattern_;
  std::vector<std::string> groups_;
  std::vector<ObjFace> faces_;
};

} // namespace

Garment parse_garment_obj(std::istream& in, const std::string& path) { return ObjParser(path).parse(in); }

Garment read_garment_obj(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::filesystem::exists(path) ? "cannot open for reading" : "no such file");
  return parse_garment_obj(in, path);
}

void print_garment_obj(const Garment& g, std::ostream& out) {
  if (const std::string error = garment_structure_error(g); !error.empty())
    throw ArgumentError("print_garment_obj: " + error);
  for (const Panel& p : g.panels)
    if (p.name.empty() || p.name.find_first_of("\r\n") != std::string::npos || p.name != trimmed(p.name))
      throw ArgumentError("print_garment_obj: panel name '" + p.name + "' cannot be written as an OBJ group");
  std::string text;
  text.reserve(static_cast<size_t>(g.V.rows() * 60 + g.P.rows() * 40 + g.F.rows() * 40));
  text += "# foldsketch garment: v = drape [m], vt = pattern [m], one g per panel, f v/vt\n";
  for (int i = 0; i < g.V.rows(); ++i)
    text += "v " + format_double(g.V(i, 0)) + ' ' + format_double(g.V(i, 1)) + ' ' + format_double(g.V(i, 2)) + '\n';
  for (int i = 0; i < g.P.rows(); ++i) text += "vt " + format_double(g.P(i, 0)) + ' ' + format_double(g.P(i, 1)) + '\n';
  int current = -1;
  for (int f = 0; f < g.F.rows(); ++f) {
    if (g.face_panel(f) != current) {
      current = g.face_panel(f);
      text += "g " + g.panels[current].name + '\n';
    }
    text += 'f';
    for (int k = 0; k < 3; ++k) text += ' ' + std::to_string(g.F(f, k) + 1) + '/' + std::to_string(g.FP(f, k) + 1);
    text += '\n';
  }
  out << text;
}

} // namespace foldsketch
