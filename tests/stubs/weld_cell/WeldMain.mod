MODULE WeldMain
  ! Tests: a name whose type its uses do not tell gets a comment, not a guess, and
  ! stubs exits 2 with the program's remaining error (issue 8, part B).
  PROC main()
    WeldSeam p10, p20, seamA;
    nSeams := nSeams + 1;
  ENDPROC
ENDMODULE
