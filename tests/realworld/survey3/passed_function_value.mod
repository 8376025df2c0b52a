MODULE RemoteMoves
    ! Both routines live in a motion module that was not given: nothing in this
    ! module says what GetNextGoal returns, only that it goes straight to TryMove.
    PROC main()
        VAR num attempts := 0;
        WHILE attempts < 2 DO
            IF TryMove(GetNextGoal()) THEN
                TPWrite "moved";
            ENDIF
            Incr attempts;
        ENDWHILE
    ENDPROC
ENDMODULE
