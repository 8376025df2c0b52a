MODULE Monitor
    ! Written for the test: checked alone, nStep is written by T_ROB1 (not loaded) with the
    ! values its code assigns, 0 among them.  The guard and the index are two reads: the
    ! robot task may set 0 between them, so the index 0 is a race the check must keep
    ! finding (only data an unknown party writes reads as an index there).
    PERS num nStep{2};
    PERS num cpm{2} := [10,20];
    VAR num x := 0;

    PROC main()
        IF nStep{1} <> 0 x := cpm{nStep{1}};
    ENDPROC
ENDMODULE
