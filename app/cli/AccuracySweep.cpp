#include "cli/AccuracySweep.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace vct::cli {

namespace {

/** A JSON value as `--set` would spell it; false for arrays, objects and null. */
bool settingText(const QJsonValue& value, std::string& out)
{
    if (value.isString())
        out = value.toString().toStdString();
    else if (value.isBool())
        out = value.toBool() ? "on" : "off";
    else if (value.isDouble())
        out = QString::number(value.toDouble(), 'g', 9).toStdString();
    else
        return false;
    return true;
}

bool readAssignments(
    const QJsonValue& value, const std::string& where, SettingAssignments& out, std::string* error)
{
    if (value.isUndefined())
        return true;
    if (!value.isObject()) {
        *error = where + " must be an object of \"key\": \"value\"";
        return false;
    }
    const QJsonObject object = value.toObject();
    for (auto it = object.begin(); it != object.end(); ++it) {
        std::string text;
        if (!settingText(it.value(), text)) {
            *error = where + "." + it.key().toStdString() + " must be a string, number or boolean";
            return false;
        }
        out.emplace_back(it.key().toStdString(), text);
    }
    return true;
}

std::string joined(const SettingAssignments& assignments)
{
    std::string out;
    for (const auto& [key, value] : assignments)
        out += (out.empty() ? "" : " ") + key + "=" + value;
    return out;
}

} // namespace

bool AccuracySweep::parse(const std::string& json, const render::RenderSettings& sceneSettings,
    AccuracySweep& sweep, std::string* error)
{
    std::string scratch;
    if (!error)
        error = &scratch;
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(QByteArray::fromStdString(json), &parseError);
    if (document.isNull() || !document.isObject()) {
        *error = document.isNull() ? "not JSON: " + parseError.errorString().toStdString() + " at offset "
                + std::to_string(parseError.offset)
                                   : "the sweep spec must be a JSON object";
        return false;
    }
    const QJsonObject root = document.object();
    for (auto it = root.begin(); it != root.end(); ++it)
        if (it.key() != QLatin1String("base") && it.key() != QLatin1String("axes")
            && it.key() != QLatin1String("presets") && !it.key().startsWith(QLatin1Char('_'))) {
            *error = "unknown field '" + it.key().toStdString()
                + "' (known: base, axes, presets; _comment is ignored)";
            return false;
        }

    SettingAssignments base;
    if (!readAssignments(root.value(QLatin1String("base")), "base", base, error))
        return false;
    render::RenderSettings baseSettings = sceneSettings;
    for (const auto& [key, value] : base)
        if (const std::string problem = baseSettings.set(key, value); !problem.empty()) {
            *error = "base: " + problem;
            return false;
        }

    std::vector<SweepPoint> candidates;
    candidates.push_back({ "base", "base", joined(base), {}, baseSettings });
    const QJsonValue axes = root.value(QLatin1String("axes"));
    if (!axes.isUndefined() && !axes.isArray()) {
        *error = "axes must be an array of {\"key\": ..., \"values\": [...]}";
        return false;
    }
    for (const QJsonValue& axisValue : axes.toArray()) {
        const QJsonObject axis = axisValue.toObject();
        const std::string key = axis.value(QLatin1String("key")).toString().toStdString();
        const QJsonValue values = axis.value(QLatin1String("values"));
        if (key.empty() || !values.isArray()) {
            *error = "every axis needs a \"key\" string and a \"values\" array";
            return false;
        }
        for (const QJsonValue& v : values.toArray()) {
            std::string text;
            if (!settingText(v, text)) {
                *error = "axis " + key + ": values must be strings, numbers or booleans";
                return false;
            }
            SweepPoint point { key + "=" + text, key, text, { { key, text } }, baseSettings };
            if (const std::string problem = point.settings.set(key, text); !problem.empty()) {
                *error = "axis " + key + ": " + problem;
                return false;
            }
            candidates.push_back(point);
        }
    }
    const QJsonValue presets = root.value(QLatin1String("presets"));
    if (!presets.isUndefined() && !presets.isArray()) {
        *error = "presets must be an array of {\"label\": ..., \"set\": {...}}";
        return false;
    }
    for (const QJsonValue& presetValue : presets.toArray()) {
        const QJsonObject preset = presetValue.toObject();
        const std::string label = preset.value(QLatin1String("label")).toString().toStdString();
        if (label.empty()) {
            *error = "every preset needs a \"label\"";
            return false;
        }
        SweepPoint point { label, "preset", {}, {}, baseSettings };
        if (!readAssignments(preset.value(QLatin1String("set")), "preset " + label, point.assignments, error))
            return false;
        point.value = joined(point.assignments);
        for (const auto& [key, value] : point.assignments)
            if (const std::string problem = point.settings.set(key, value); !problem.empty()) {
                *error = "preset " + label + ": " + problem;
                return false;
            }
        candidates.push_back(point);
    }

    // An axis value equal to the base's, or a preset equal to the defaults, would be measured twice. Equal
    // describe() text (every field as --stats prints it) means equal settings. A preset names its twin in the
    // label; an axis passing through the base goes without saying.
    sweep.m_points.clear();
    for (const SweepPoint& candidate : candidates) {
        bool merged = false;
        for (SweepPoint& kept : sweep.m_points)
            if (kept.settings.describe() == candidate.settings.describe()) {
                if (candidate.setting == "preset")
                    kept.label += " = " + candidate.label;
                merged = true;
                break;
            }
        if (!merged)
            sweep.m_points.push_back(candidate);
    }
    return true;
}

} // namespace vct::cli
