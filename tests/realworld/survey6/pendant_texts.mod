MODULE pendant_texts
  ! A pendant menu in the style of the survey's multilingual cells: every text is
  ! an array indexed by the language number, and the arrays and the language
  ! number live in a text module that is not given.
  PERS num nAnswer := 0;

  PROC main()
    TPWrite sTitle{nLanguage};
    TPReadFK nAnswer, sQuestion{nLanguage}, sYes{nLanguage}, "", "", "", sNo{nLanguage};
  ENDPROC
ENDMODULE
