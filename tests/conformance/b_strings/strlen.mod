MODULE MainModule
  ! Tests: StrLen counts characters; "" counts 0; a doubled quote "" inside a literal is one character.
  PROC main()
    TPWrite "robotics=" \Num:=StrLen("Robotics");
    TPWrite "empty=" \Num:=StrLen("");
    TPWrite "quoted=" \Num:=StrLen("say ""hi""");
    TPWrite "backslash=" \Num:=StrLen("a\\b");
  ENDPROC
ENDMODULE
