MODULE MainModule
  ! Tests: SetGO writes an integer to a group output; GOutput reads it back.
  VAR signalgo goCode;
  PROC main()
    AliasIO "GO1", goCode;
    SetGO goCode, 12;
    TPWrite "go=" \Num:=GOutput(goCode);
    SetGO goCode, 3;
    TPWrite "go=" \Num:=GOutput(goCode);
  ENDPROC
ENDMODULE
