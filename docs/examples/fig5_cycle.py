"""
The paper's Fig. 5 cycle
========================

Stub.
"""

# %%
print("hello")
