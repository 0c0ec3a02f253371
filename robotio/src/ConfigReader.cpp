#include "dynamap/robotio/ConfigReader.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

namespace dynamap::robotio {

namespace {

std::string Describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsMap()) return "a mapping";
  if (node.IsSequence()) return "a list";
  return "'" + node.Scalar() + "'";
}

std::string RangeText(double min, double max) {
  std::ostringstream out;
  out << "[" << min << ", " << max << "]";
  return out.str();
}

}  // namespace

ConfigNode::ConfigNode(YAML::Node node, std::string file, std::string path)
    : ConfigNode(std::move(node), std::move(file), std::move(path), std::make_shared<Usage>()) {}

ConfigNode::ConfigNode(YAML::Node node, std::string file, std::string path,
                       std::shared_ptr<Usage> usage)
    : node_(std::move(node)),
      file_(std::move(file)),
      path_(std::move(path)),
      usage_(std::move(usage)) {
  if (!node_.IsMap()) {
    throw ConfigError(file_ + ": " + (path_.empty() ? std::string("the document") : "key '" + path_ + "'") +
                      " must be a mapping of keys, found " + Describe(node_));
  }
}

std::string ConfigNode::KeyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void ConfigNode::Fail(const std::string& key, const std::string& message) const {
  throw ConfigError(file_ + ": key '" + KeyPath(key) + "': " + message);
}

bool ConfigNode::Has(const std::string& key) const { return static_cast<bool>(node_[key]); }

YAML::Node ConfigNode::Get(const std::string& key) {
  usage_->read.insert(KeyPath(key));
  return node_[key];
}

YAML::Node ConfigNode::Raw(const std::string& key) {
  usage_->raw.insert(KeyPath(key));
  return Get(key);
}

void ConfigNode::Read(const std::string& key, double* value, double min, double max) {
  const YAML::Node n = Get(key);
  if (!n) return;
  double parsed = 0.0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, parsed) || !std::isfinite(parsed)) {
    Fail(key, "expected a number in " + RangeText(min, max) + ", found " + Describe(n));
  }
  if (parsed < min || parsed > max) {
    Fail(key, "value " + n.Scalar() + " is out of range, allowed " + RangeText(min, max));
  }
  *value = parsed;
}

void ConfigNode::Read(const std::string& key, int* value, int min, int max) {
  const YAML::Node n = Get(key);
  if (!n) return;
  int parsed = 0;
  if (!n.IsScalar() || !YAML::convert<int>::decode(n, parsed)) {
    Fail(key, "expected an integer in " + RangeText(min, max) + ", found " + Describe(n));
  }
  if (parsed < min || parsed > max) {
    Fail(key, "value " + n.Scalar() + " is out of range, allowed " + RangeText(min, max));
  }
  *value = parsed;
}

void ConfigNode::Read(const std::string& key, bool* value) {
  const YAML::Node n = Get(key);
  if (!n) return;
  bool parsed = false;
  if (!n.IsScalar() || !YAML::convert<bool>::decode(n, parsed)) {
    Fail(key, "expected true or false, found " + Describe(n));
  }
  *value = parsed;
}

void ConfigNode::Read(const std::string& key, std::string* value) {
  const YAML::Node n = Get(key);
  if (!n) return;
  if (!n.IsScalar()) Fail(key, "expected a text value, found " + Describe(n));
  *value = n.Scalar();
}

void ConfigNode::ReadChoice(const std::string& key, std::string* value,
                            const std::vector<std::string>& allowed) {
  std::string parsed = *value;
  Read(key, &parsed);
  for (const auto& word : allowed) {
    if (parsed == word) {
      *value = parsed;
      return;
    }
  }
  std::string list;
  for (const auto& word : allowed) list += (list.empty() ? "" : ", ") + word;
  Fail(key, "'" + parsed + "' is not one of: " + list);
}

void ConfigNode::ReadVector(const std::string& key, Eigen::VectorXd* value, int size, double min,
                            double max) {
  const YAML::Node n = Get(key);
  if (!n) return;
  if (!n.IsSequence() || static_cast<int>(n.size()) != size) {
    Fail(key, "expected a list of " + std::to_string(size) + " numbers, found " + Describe(n));
  }
  Eigen::VectorXd parsed(size);
  for (int i = 0; i < size; ++i) {
    double element = 0.0;
    if (!n[i].IsScalar() || !YAML::convert<double>::decode(n[i], element) ||
        !std::isfinite(element)) {
      Fail(key, "element " + std::to_string(i) + " must be a number, found " + Describe(n[i]));
    }
    if (element < min || element > max) {
      Fail(key, "element " + std::to_string(i) + " = " + n[i].Scalar() +
                    " is out of range, allowed " + RangeText(min, max));
    }
    parsed[i] = element;
  }
  *value = parsed;
}

double ConfigNode::RequireDouble(const std::string& key, double min, double max) {
  if (!Has(key)) Fail(key, "is required (a number in " + RangeText(min, max) + ")");
  double value = 0.0;
  Read(key, &value, min, max);
  return value;
}

int ConfigNode::RequireInt(const std::string& key, int min, int max) {
  if (!Has(key)) Fail(key, "is required (an integer in " + RangeText(min, max) + ")");
  int value = 0;
  Read(key, &value, min, max);
  return value;
}

std::string ConfigNode::RequireString(const std::string& key) {
  if (!Has(key)) Fail(key, "is required (a text value)");
  std::string value;
  Read(key, &value);
  return value;
}

Eigen::VectorXd ConfigNode::RequireVector(const std::string& key, int size, double min,
                                          double max) {
  if (!Has(key)) {
    Fail(key, "is required (a list of " + std::to_string(size) + " numbers)");
  }
  Eigen::VectorXd value;
  ReadVector(key, &value, size, min, max);
  return value;
}

ConfigNode ConfigNode::Child(const std::string& key) {
  if (!Has(key)) Fail(key, "is required (a mapping)");
  const YAML::Node n = Get(key);
  if (!n.IsMap()) Fail(key, "expected a mapping, found " + Describe(n));
  return ConfigNode(n, file_, KeyPath(key), usage_);
}

std::optional<ConfigNode> ConfigNode::OptionalChild(const std::string& key) {
  if (!Has(key)) return std::nullopt;
  return Child(key);
}

std::vector<ConfigNode> ConfigNode::ChildList(const std::string& key) {
  std::vector<ConfigNode> children;
  const YAML::Node n = Get(key);
  if (!n || n.IsNull()) return children;
  if (!n.IsSequence()) Fail(key, "expected a list, found " + Describe(n));
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string path = KeyPath(key) + "[" + std::to_string(i) + "]";
    if (!n[i].IsMap()) {
      throw ConfigError(file_ + ": key '" + path + "': expected a mapping, found " +
                        Describe(n[i]));
    }
    children.push_back(ConfigNode(n[i], file_, path, usage_));
  }
  return children;
}

void ConfigNode::Finish() const { CheckUsed(node_, path_); }

void ConfigNode::CheckUsed(const YAML::Node& node, const std::string& path) const {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      CheckUsed(node[i], path + "[" + std::to_string(i) + "]");
    }
    return;
  }
  if (!node.IsMap()) return;
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>();
    const std::string full = path.empty() ? key : path + "." + key;
    if (usage_->read.count(full) == 0) {
      std::string known;
      const std::string prefix = path.empty() ? "" : path + ".";
      for (const auto& k : usage_->read) {
        if (k.compare(0, prefix.size(), prefix) == 0 &&
            k.find_first_of(".[", prefix.size()) == std::string::npos) {
          known += (known.empty() ? "" : ", ") + k.substr(prefix.size());
        }
      }
      throw ConfigError(file_ + ": key '" + full + "' is not a known setting" +
                        (known.empty() ? std::string() : " (known here: " + known + ")"));
    }
    if (usage_->raw.count(full) == 0) CheckUsed(entry.second, full);
  }
}

namespace internal {

YAML::Node LoadYamlFile(const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw ConfigError(file + ": file not found");
  }
  try {
    return YAML::LoadFile(file);
  } catch (const YAML::ParserException& e) {
    throw ConfigError(file + ": malformed YAML at line " + std::to_string(e.mark.line + 1) +
                      ", column " + std::to_string(e.mark.column + 1) + ": " + e.msg);
  } catch (const YAML::BadFile&) {
    throw ConfigError(file + ": cannot be read");
  }
}

YAML::Node LoadYamlText(const std::string& text, const std::string& name) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw ConfigError(name + ": malformed YAML at line " + std::to_string(e.mark.line + 1) +
                      ", column " + std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
}

}  // namespace internal
}  // namespace dynamap::robotio
