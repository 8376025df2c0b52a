! expect: exit 2 [RMC206]
! Two aggregates added with no type to tell: a type error (once: struct.error in to_num).
MODULE UntypedSum
  PROC main()
    TPWrite "sum" \Pos:=-([0, 1, 2] + [3, 4, 5]);
  ENDPROC
ENDMODULE
