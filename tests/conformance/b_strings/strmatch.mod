MODULE MainModule
  ! Tests: StrMatch returns the position of the first occurrence of Pattern at or after ChPos,
  ! and StrLen+1 when the pattern does not occur.
  PROC main()
    TPWrite "bo=" \Num:=StrMatch("Robotics", 1, "bo");
    TPWrite "ot=" \Num:=StrMatch("Robotics", 1, "ot");
    TPWrite "o_from5=" \Num:=StrMatch("Robotics", 5, "o");
    TPWrite "none=" \Num:=StrMatch("Robotics", 1, "xyz");
    TPWrite "later=" \Num:=StrMatch("abcabc", 2, "abc");
  ENDPROC
ENDMODULE
