MODULE Writer
  VAR num seen := 0;
  PROC main()
    Set doOther;                         ! SHARED
    IF doOther = 1 seen := 1;            ! LOCAL
  ENDPROC
ENDMODULE
