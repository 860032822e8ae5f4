#pragma once
/// @file
/// Editing the text of a YAML parameter file value by value, so that everything not edited
/// (comments with the sources of the other values, layout, order) stays exactly as it was: how
/// the fit commands write fitted files (docs/fitting.md).
///
/// Understands the subset the project's files use: block mappings by indentation (`key: value`
/// lines, `# comment` after a value) and one-line flow mappings (`fl: {file: a.tir, x: 1}`).
/// A key is addressed by its dotted path from the top ("heat_generation.p1").

#include <string>
#include <string_view>
#include <vector>

namespace hotlap::ident {

class YamlTextEditor {
 public:
  /// `file_for_messages` names the file in errors.
  YamlTextEditor(const std::string& text, std::string file_for_messages);

  /// Sets the scalar at `dotted_key` to `value` (written as given) and, if `comment` is not
  /// empty, replaces the comment after it (`# comment`). The key may be on its own line or inside
  /// a one-line flow mapping of its parent (the comment then goes at the end of that line).
  /// InputError naming the file and key if there is no such scalar.
  void SetValue(std::string_view dotted_key, const std::string& value,
                const std::string& comment = {});

  /// True if the file has a scalar at `dotted_key`.
  bool Has(std::string_view dotted_key) const;

  /// Puts `comment_lines` (each written as "# line") before the first line.
  void PrependComments(const std::vector<std::string>& comment_lines);

  /// The edited text.
  std::string Text() const;

 private:
  struct Line {
    std::string text;
    std::string path;     // dotted key of a `key:` line, empty otherwise
    size_t value_at = 0;  // index just after the colon
  };
  void Index();
  // Position of the value part [begin, end) and of the comment ('#', or npos) in `line`.
  static void Split(const std::string& line, size_t from, size_t* value_begin, size_t* value_end,
                    size_t* comment);
  // Finds `key` in the flow mapping of `line` after `from`; sets the value range; false if absent.
  static bool FindInFlow(const std::string& line, size_t from, std::string_view key, size_t* begin,
                         size_t* end);

  std::vector<Line> lines_;
  std::string file_;
  bool trailing_newline_ = true;
};

}  // namespace hotlap::ident
