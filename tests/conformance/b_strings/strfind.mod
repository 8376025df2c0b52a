MODULE MainModule
  ! Tests: StrFind returns the first position >= ChPos whose character is in Set (or, with
  ! \NotInSet, not in Set), and StrLen+1 when there is none.
  PROC main()
    TPWrite "vowel=" \Num:=StrFind("Robotics", 1, "aeiou");
    TPWrite "vowel3=" \Num:=StrFind("Robotics", 3, "aeiou");
    TPWrite "digit=" \Num:=StrFind("Robotics", 1, STR_DIGIT);
    TPWrite "notvowel=" \Num:=StrFind("Robotics", 1, "aeiou" \NotInSet);
    TPWrite "notupper=" \Num:=StrFind("ABc1", 1, STR_UPPER \NotInSet);
  ENDPROC
ENDMODULE
