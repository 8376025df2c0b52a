MODULE MainModule
  ! Tests: StrPart with a part reaching past the end of the string is a run-time error
  ! (error number undocumented).
  PROC main()
    VAR string s;
    TPWrite "before";
    s := StrPart("Robotics", 7, 5);
    TPWrite "not reached";
  ENDPROC
ENDMODULE
