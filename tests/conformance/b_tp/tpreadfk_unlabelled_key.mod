MODULE MainModule
  ! Tests: a function key without a label (stEmpty) is not offered; answering it is refused.
  PROC main()
    VAR num key;
    TPReadFK key, "Continue?", "Yes", "No", stEmpty, stEmpty, stEmpty;
    TPWrite "chose key " \Num:=key;
  ENDPROC
ENDMODULE
