// Strict YAML reading shared by every module's config parser (STYLE rule 4): an unknown
// key, a missing required key, a wrong type or an out-of-range value is an error that
// names the file, the key path and what was allowed. Defaults live in the config structs.
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamap/robotio/Expected.hpp"

namespace dynamap::robotio {

// Thrown inside a parser and turned into an Error at the parser's boundary (ParseFile).
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A view of one YAML mapping that remembers which keys were read, so that Finish() can
// reject keys nobody asked for (typos must not be silently ignored).
class ConfigNode {
 public:
  ConfigNode(YAML::Node node, std::string file, std::string path);

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] bool Has(const std::string& key) const;

  // Optional scalar: leaves *value (the struct's default) unchanged when the key is absent.
  void Read(const std::string& key, double* value, double min, double max);
  void Read(const std::string& key, int* value, int min, int max);
  void Read(const std::string& key, bool* value);
  void Read(const std::string& key, std::string* value);
  // One of the allowed words.
  void ReadChoice(const std::string& key, std::string* value,
                  const std::vector<std::string>& allowed);
  // Fixed-size numeric list, e.g. "translation: [x, y, z]".
  void ReadVector(const std::string& key, Eigen::VectorXd* value, int size, double min,
                  double max);

  // Required variants: a missing key is an error.
  [[nodiscard]] double RequireDouble(const std::string& key, double min, double max);
  [[nodiscard]] int RequireInt(const std::string& key, int min, int max);
  [[nodiscard]] std::string RequireString(const std::string& key);
  [[nodiscard]] Eigen::VectorXd RequireVector(const std::string& key, int size, double min,
                                              double max);

  // Nested mapping / list of mappings.
  [[nodiscard]] ConfigNode Child(const std::string& key);
  [[nodiscard]] std::optional<ConfigNode> OptionalChild(const std::string& key);
  [[nodiscard]] std::vector<ConfigNode> ChildList(const std::string& key);
  // Raw access for shapes the helpers above do not cover (the key counts as used).
  [[nodiscard]] YAML::Node Raw(const std::string& key);

  // Throws ConfigError when this mapping, or any mapping below it, holds a key that no
  // parser read (ParseYamlFile calls it on the root, so nested parsers need not).
  void Finish() const;
  // Throws ConfigError "file: key 'path.key': message".
  [[noreturn]] void Fail(const std::string& key, const std::string& message) const;

 private:
  [[nodiscard]] std::string KeyPath(const std::string& key) const;
  [[nodiscard]] YAML::Node Get(const std::string& key);

  struct Usage {
    std::set<std::string> read;  // Full key paths that a parser asked for.
    std::set<std::string> raw;   // Full key paths handed out whole through Raw().
  };
  ConfigNode(YAML::Node node, std::string file, std::string path, std::shared_ptr<Usage> usage);
  void CheckUsed(const YAML::Node& node, const std::string& path) const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  std::shared_ptr<Usage> usage_;
};

// Loads `file` and runs `parse` on its root mapping; any ConfigError, YAML syntax error or
// missing file becomes an Error whose message names the file (and key, where known).
template <typename T>
Expected<T> ParseYamlFile(const std::string& file, const std::function<T(ConfigNode&)>& parse);

// Same for YAML text already in memory; `name` stands for the file in messages.
template <typename T>
Expected<T> ParseYamlText(const std::string& text, const std::string& name,
                          const std::function<T(ConfigNode&)>& parse);

namespace internal {
// Loads the YAML root (throws ConfigError naming the file on I/O or syntax errors).
YAML::Node LoadYamlFile(const std::string& file);
YAML::Node LoadYamlText(const std::string& text, const std::string& name);
}  // namespace internal

template <typename T>
Expected<T> ParseYamlFile(const std::string& file, const std::function<T(ConfigNode&)>& parse) {
  try {
    ConfigNode root(internal::LoadYamlFile(file), file, "");
    T result = parse(root);
    root.Finish();
    return result;
  } catch (const ConfigError& e) {
    return Error{e.what()};
  } catch (const YAML::Exception& e) {
    return Error{file + ": " + e.what()};
  }
}

template <typename T>
Expected<T> ParseYamlText(const std::string& text, const std::string& name,
                          const std::function<T(ConfigNode&)>& parse) {
  try {
    ConfigNode root(internal::LoadYamlText(text, name), name, "");
    T result = parse(root);
    root.Finish();
    return result;
  } catch (const ConfigError& e) {
    return Error{e.what()};
  } catch (const YAML::Exception& e) {
    return Error{name + ": " + e.what()};
  }
}

}  // namespace dynamap::robotio
