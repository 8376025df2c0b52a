MODULE MainModule
  ! Tests: TPReadFK returns 5 for the fifth key, with empty keys (stEmpty) in between.
  PROC main()
    VAR num key;
    TPReadFK key, "Select mode", "Auto", stEmpty, stEmpty, stEmpty, "Quit";
    TPWrite "key=" \Num:=key;
    IF key = 5 TPWrite "quitting";
  ENDPROC
ENDMODULE
