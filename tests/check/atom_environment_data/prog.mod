MODULE PickCell
    ! Polls for a part, grips it, releases it, again and again.
    VAR signaldi part;
    VAR signaldo grip;

    PROC main()
        AliasIO "DI_PART", part;
        AliasIO "DO_GRIP", grip;
        WHILE TRUE DO
            IF part = 1 THEN
                SetDO grip, 1;
                SetDO grip, 0;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
