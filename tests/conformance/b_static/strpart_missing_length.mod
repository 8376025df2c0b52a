MODULE MainModule
  ! Tests: StrPart requires Str, ChPos and Len; leaving out Len is a static argument error.
  PROC main()
    VAR string s;
    TPWrite "must not run";
    s := StrPart("Robotics", 1);
  ENDPROC
ENDMODULE
