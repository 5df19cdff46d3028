#!/usr/bin/python3
"""Writes a toy llama-architecture GGUF model with random weights, for
running a real llama-server against apprentice where no trained model can
be had (docs/llm.md, "A real llama-server"). The model says nothing useful:
it exercises the server's protocol, log-probabilities, stop strings and
byte-fallback tokens, not language.

It takes its tokenizer from one of the vocab-only files that llama.cpp
ships (models/ggml-vocab-llama-spm.gguf) and needs llama.cpp's gguf-py:

  PYTHONPATH=/path/to/llama.cpp/gguf-py /usr/bin/python3 scripts/toy-gguf.py \\
      /path/to/llama.cpp/models/ggml-vocab-llama-spm.gguf toy.gguf

Options: --embedding N (64), --layers N (2), --seed N (0), --context N (4096).
"""
import argparse
import sys

import numpy as np

try:
    import gguf
except ImportError:
    sys.exit("toy-gguf.py: needs llama.cpp's gguf-py: PYTHONPATH=/path/to/llama.cpp/gguf-py")


def field_value(field):
    """A field's value. gguf-py's ReaderField has contents() since mid 2025;
    older releases (llama.cpp of early 2025) keep the raw parts only."""
    if hasattr(field, "contents"):
        return field.contents()
    def one(index):
        part = field.parts[index]
        if field.types[-1] == gguf.GGUFValueType.STRING:
            return bytes(part).decode("utf-8")
        return part.tolist()[0]
    if field.types[0] == gguf.GGUFValueType.ARRAY:
        return [one(index) for index in field.data]
    return one(field.data[0])


def tokenizer_fields(reader):
    """The vocab file's tokenizer.* fields, as (key, value, type)."""
    out = []
    for key, field in reader.fields.items():
        if key.startswith("tokenizer."):
            out.append((key, field_value(field), field.types))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("vocab", help="a vocab-only GGUF of llama.cpp (models/ggml-vocab-llama-spm.gguf)")
    parser.add_argument("out", help="the model file to write")
    parser.add_argument("--embedding", type=int, default=64)
    parser.add_argument("--layers", type=int, default=2)
    parser.add_argument("--heads", type=int, default=4)
    parser.add_argument("--context", type=int, default=4096)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()

    reader = gguf.GGUFReader(args.vocab)
    tokens = field_value(reader.fields["tokenizer.ggml.tokens"])
    vocab = len(tokens)
    embd, heads, ff = args.embedding, args.heads, 2 * args.embedding
    rng = np.random.default_rng(args.seed)

    writer = gguf.GGUFWriter(args.out, "llama")
    writer.add_name("apprentice toy (random weights)")
    writer.add_context_length(args.context)
    writer.add_embedding_length(embd)
    writer.add_block_count(args.layers)
    writer.add_feed_forward_length(ff)
    writer.add_head_count(heads)
    writer.add_head_count_kv(heads)
    writer.add_rope_dimension_count(embd // heads)
    writer.add_layer_norm_rms_eps(1e-5)
    writer.add_vocab_size(vocab)
    writer.add_file_type(gguf.LlamaFileType.ALL_F32)
    for key, value, types in tokenizer_fields(reader):
        main_type = types[0]
        if main_type == gguf.GGUFValueType.ARRAY:
            writer.add_array(key, value)
        elif main_type == gguf.GGUFValueType.STRING:
            writer.add_string(key, value)
        elif main_type == gguf.GGUFValueType.BOOL:
            writer.add_bool(key, bool(value))
        else:
            writer.add_uint32(key, int(value))

    def weights(*shape, scale=0.02):
        return (rng.standard_normal(shape) * scale).astype(np.float32)

    writer.add_tensor("token_embd.weight", weights(vocab, embd, scale=1.0))
    writer.add_tensor("output_norm.weight", np.ones(embd, dtype=np.float32))
    writer.add_tensor("output.weight", weights(vocab, embd, scale=0.5))
    for layer in range(args.layers):
        prefix = f"blk.{layer}."
        writer.add_tensor(prefix + "attn_norm.weight", np.ones(embd, dtype=np.float32))
        for name in ("attn_q", "attn_k", "attn_v", "attn_output"):
            writer.add_tensor(prefix + name + ".weight", weights(embd, embd))
        writer.add_tensor(prefix + "ffn_norm.weight", np.ones(embd, dtype=np.float32))
        writer.add_tensor(prefix + "ffn_gate.weight", weights(ff, embd))
        writer.add_tensor(prefix + "ffn_up.weight", weights(ff, embd))
        writer.add_tensor(prefix + "ffn_down.weight", weights(embd, ff))

    writer.write_header_to_file()
    writer.write_kv_data_to_file()
    writer.write_tensors_to_file()
    writer.close()
    print(f"{args.out}: llama, {args.layers} layers, {embd} wide, {vocab} tokens, random weights (seed {args.seed})")


if __name__ == "__main__":
    main()
