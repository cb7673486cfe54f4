"""Check the README's Python client recipe: every calculation through the generated client.

Run by `.ci/run` after it has generated and installed the client with openapi-python-client
(`python_client_check.py BASE_URL`, with the server running at BASE_URL). For each calculation
in `GET /v1/calculations`, the operation's module is found from its tag and operation id (as
the generator names them), its example is parsed into the typed request model (`from_dict`),
sent with `sync_detailed`, and the answer must be 200 and parsed into the typed envelope, whose
`to_dict()` holds the same result keys the server sent. Then one invalid request must come back
422 with the problem's pointer. Exits non-zero naming the first failure.
"""

import importlib
import json
import sys
import typing
import urllib.request

from stribeck_client import Client
from stribeck_client.api.lubricants import lubricants_viscosity_index
from stribeck_client.models import ViscosityIndexInput


def module_name(name: str) -> str:
    """The generator's module name for a tag or an operation id."""
    return name.replace("-", "_")


def main(base: str) -> None:
    client = Client(base_url=base, raise_on_unexpected_status=True)
    with urllib.request.urlopen(f"{base}/openapi.json") as r:
        doc = json.load(r)
    with urllib.request.urlopen(f"{base}/v1/calculations") as r:
        calculations = json.load(r)["calculations"]
    assert calculations, "no calculations listed"
    for calc in calculations:
        op = doc["paths"][calc["path"]]["post"]
        tag = module_name(op["tags"][0])
        module = importlib.import_module(
            f"stribeck_client.api.{tag}.{module_name(op['operationId'])}"
        )
        body_type = typing.get_type_hints(module.sync_detailed)["body"]
        body = body_type.from_dict(calc["example"])
        response = module.sync_detailed(client=client, body=body)
        assert response.status_code == 200, f"{calc['path']}: {response.status_code} {response.content[:300]!r}"
        envelope = response.parsed
        sent = json.loads(response.content)
        typed = envelope.to_dict()
        assert set(typed) == {"result", "effects", "solver", "warnings"}, f"{calc['path']}: {set(typed)}"
        assert set(typed["result"]) == set(sent["result"]), f"{calc['path']}: result keys differ"
        assert set(typed["effects"]) == set(calc["effects"]), f"{calc['path']}: effects differ"
    invalid = ViscosityIndexInput(kinematic_viscosity_40c_mm2_s=-73.3, kinematic_viscosity_100c_mm2_s=8.86)
    response = lubricants_viscosity_index.sync_detailed(client=client, body=invalid)
    assert response.status_code == 422, response.status_code
    problem = json.loads(response.content)
    assert [e["pointer"] for e in problem["errors"]] == ["/kinematic_viscosity_40c_mm2_s"], problem
    print(f"python client: {len(calculations)} calculations answered through the generated client; a 422 named its field")


if __name__ == "__main__":
    main(sys.argv[1])
