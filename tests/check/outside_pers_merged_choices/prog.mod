MODULE OutsideChoices
    ! Issue 28 (the gantry tasks' monitoring loop): a PC or another task writes the PERS
    ! command, step and flags, so each read takes any value of its domain. Every IF below
    ! reads them again. Merged into one transition, their choices multiplied: a transition
    ! per combination, 145,423 of them between 24 states. A merged step now stops before an
    ! instruction that chooses once a choice was made, so the choices add up instead (560
    ! transitions between 36 states).
    PERS string stCommand := "";
    PERS num nStep := 0;
    PERS bool bSkip := FALSE;
    VAR num nSequence := 0;

    PROC main()
        WHILE TRUE DO
            rSequence;
        ENDWHILE
    ENDPROC

    PROC rSequence()
        IF (stCommand = "Weld" OR stCommand = "NoWeld") AND 1 <= nStep THEN
            IF nSequence = 0 AND stCommand = "Weld" nSequence := 1;
            IF nSequence = 1 AND bSkip = FALSE nSequence := 2;
            IF nSequence = 2 AND stCommand = "NoWeld" nSequence := 3;
            IF nSequence = 3 AND nStep = 2 nSequence := 0;
            IF stCommand = "Weld" AND bSkip nSequence := 1;
        ELSE
            nSequence := 0;
        ENDIF
    ENDPROC
ENDMODULE
