MODULE MainModule
  ! Tests: StrMemb tells whether the character at ChPos belongs to Set.
  PROC main()
    TPWrite "pos2=" \Bool:=StrMemb("Robotics", 2, "aeiou");
    TPWrite "pos3=" \Bool:=StrMemb("Robotics", 3, "aeiou");
    TPWrite "digit=" \Bool:=StrMemb("a7b", 2, STR_DIGIT);
    TPWrite "upper=" \Bool:=StrMemb("Robotics", 1, STR_UPPER);
  ENDPROC
ENDMODULE
