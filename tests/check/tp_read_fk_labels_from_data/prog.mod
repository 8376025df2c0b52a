MODULE TpReadFkLabelsFromData
    ! The labels come from a text table (in the survey, of a module not given: its stub
    ! gives ""). All empty and no break: rapidmc cannot tell a dialog that would block
    ! from data it does not know, so it offers every key instead of a deadlock.
    PERS string sYes{2} := ["", ""];
    PERS string sNo{2} := ["", ""];
    PERS num nLanguage := 1;
    VAR num key := 0;

    PROC main()
        TPReadFK key, "Continue?", sYes{nLanguage}, stEmpty, stEmpty, stEmpty, sNo{nLanguage};
    ENDPROC
ENDMODULE
