MODULE MainModule
  ! Tests: StrPart with ChPos 0 (outside the string) is a recoverable run-time error.
  PROC main()
    VAR string s;
    s := StrPart("Robotics", 0, 2);
    TPWrite "not reached";
  ERROR
    TPWrite "error for position 0";
  ENDPROC
ENDMODULE
