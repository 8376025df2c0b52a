MODULE Macro
    ! Written for the test (issue 28): a PC writes the macro's two parts; no task of the
    ! backup writes them. The task waits until both are filled, then cuts the first one's
    ! letter: the read after the wait sees the text the wait saw, not "" again.
    PERS string stMacro{2} := ["", ""];
    PERS num nMacros := 0;
    VAR string letter := "";

    PROC main()
        WHILE TRUE DO
            WaitUntil stMacro{1} <> "" AND stMacro{2} <> "";
            letter := StrPart(stMacro{1}, 1, 1);
            IF letter = "M" THEN
                nMacros := nMacros + 1;
            ENDIF
            WaitUntil stMacro{1} = "";
        ENDWHILE
    ENDPROC
ENDMODULE
