MODULE string_escapes
  ! Tests: string literal escapes: "" is one quote, \\ one backslash, and
  ! \hh the character with hex code hh (\41 = "A", \42 = "B").
  PROC main()
    TPWrite "say ""hi""";
    TPWrite "back\\slash";
    TPWrite "\41\42C";
    TPWrite "len=" \Num:=StrLen("""\\\41");
  ENDPROC
ENDMODULE
