MODULE FileRecipe
    ! A recipe file: a mode word read with ReadStr and a count read with ReadNum.
    VAR iodev recipe;
    VAR string line := "";
    VAR num count := 0;
    VAR num mode := 0;

    PROC main()
        Open "HOME:" \File:="recipe.txt", recipe \Read;
        line := ReadStr(recipe);
        count := ReadNum(recipe);
        Close recipe;
        IF line = "FAST" THEN
            mode := 1;
        ELSEIF line = "SLOW" THEN
            mode := 2;
        ENDIF
        IF count > 10 THEN
            mode := mode + 10;
        ENDIF
    ERROR
        IF ERRNO = ERR_RCVDATA THEN
            mode := -1;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
