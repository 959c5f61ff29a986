"""The bundled campaign's manifest (levels/campaign.json), written in one layout by the tools that change it
(tools/balance-campaign: the order; tools/renumber-levels: the file names and the renumbering history)."""
import json


def manifest_text(campaign):
    """campaign: the parsed manifest, its episodes' "levels" in the order to write."""
    lines = ['{', '  "$schema": "schema/campaign.schema.json",', '  "format": 1,',
             '  "title": %s,' % json.dumps(campaign["title"]), '  "episodes": [']
    episodes = []
    for episode in campaign["episodes"]:
        names = (",\n" + " " * 17).join(json.dumps(name) for name in episode["levels"])
        episodes.append('    { "id": %s, "title": %s,\n      "levels": [%s] }'
                        % (json.dumps(episode["id"]), json.dumps(episode["title"]), names))
    lines.append(",\n".join(episodes))
    if campaign.get("renumbered"):
        steps = []
        for step in campaign["renumbered"]:
            pairs = ["%s: %s" % (json.dumps(old), json.dumps(new)) for old, new in step["ids"].items()]
            rows = (",\n" + " " * 15).join(", ".join(pairs[i:i + 8]) for i in range(0, len(pairs), 8))
            steps.append('    { "numbering": %d,\n      "ids": { %s } }' % (step["numbering"], rows))
        lines += ["  ],", '  "renumbered": [', ",\n".join(steps)]
    lines += ["  ]", "}", ""]
    return "\n".join(lines)
